#include "sampling/core/input_file.h"

#include "sampling/core/errors.h"

#include <cerrno>
#include <cstring>

namespace pdrt {

std::ifstream open_for_reading(const std::filesystem::path& file, std::ios::openmode mode) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw InputError(file.string() + ": cannot open: " + std::strerror(EISDIR) + ", expected a file");
  errno = 0;
  std::ifstream in(file, mode | std::ios::in);
  if (!in) throw InputError(file.string() + ": cannot open: " + std::strerror(errno ? errno : ENOENT));
  return in;
}

}  // namespace pdrt
