#include "sampling/core/atomic_file.h"

#include "sampling/core/errors.h"
#include "sampling/core/output_directory.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace pdrt {
namespace fs = std::filesystem;

namespace {
fs::path temp_beside(const fs::path& path) {
  std::string name = ".";  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "." + string
  name += path.filename().string();
  name += ".tmp";
  name += std::to_string(::getpid());
  return path.parent_path() / name;
}
fs::path dir_of(const fs::path& path) { return path.parent_path().empty() ? fs::path(".") : path.parent_path(); }

// The directory itself when it exists, else its nearest existing ancestor (where the missing
// ones will be created).
fs::path nearest_existing(fs::path dir) {
  std::error_code ec;
  while (!fs::exists(dir, ec)) {
    fs::path up = dir.parent_path();
    if (up.empty() || up == dir) return up.empty() ? fs::path(".") : up;
    dir = up;
  }
  return dir;
}
}  // namespace

void check_writable(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path.string() + ": is a directory, expected a file path");
  const fs::path dir = dir_of(path), base = nearest_existing(dir);
  if (!fs::is_directory(base, ec))
    throw InputError(path.string() + ": cannot create directory '" + dir.string() + "': '" + base.string() +
                     "' is not a directory");
  if (::access(base.c_str(), W_OK) != 0)
    throw InputError(path.string() + ": directory '" + base.string() + "' is not writable (" + std::strerror(errno) +
                     ")");
}

void write_path_atomically(const fs::path& path, const std::function<void(const fs::path&)>& writer) {
  check_writable(path);
  const fs::path dir = dir_of(path);
  create_output_directory(dir);
  fs::path tmp = temp_beside(path);
  try {
    writer(tmp);
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError(path.string() + ": cannot write (" + ec.message() + ")");
  }
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& writer) {
  write_path_atomically(path, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(path.string() + ": cannot open for writing (" + std::strerror(errno) + ")");
    writer(out);
    out.flush();
    if (!out) throw InputError(path.string() + ": write failed (" + std::strerror(errno) + ")");
  });
}

}  // namespace pdrt
