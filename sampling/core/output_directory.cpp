#include "sampling/core/output_directory.h"

#include "sampling/core/errors.h"
#include "sampling/core/warnings.h"

namespace pdrt {
namespace fs = std::filesystem;

void create_output_directory(const fs::path& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  // The topmost missing directory: the one whose creation the user should hear about.
  fs::path top = dir;
  for (fs::path up = dir.parent_path(); !up.empty() && up != top && !fs::exists(up, ec); up = up.parent_path())
    top = up;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create directory (" + ec.message() + ")");
  warn("pdrt: created directory '" + top.string() + "'" + (top == dir ? "" : " for '" + dir.string() + "'"));
}

}  // namespace pdrt
