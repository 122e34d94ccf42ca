#include "sampling/core/install_paths.h"

#include <cstdlib>
#include <sstream>

namespace pdrt {
namespace fs = std::filesystem;

fs::path executable_path() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

std::optional<fs::path> installed_path(const fs::path& relative) {
  const fs::path exe = executable_path();
  if (exe.empty()) return std::nullopt;
  std::error_code ec;
  const fs::path p = exe.parent_path().parent_path() / relative;
  if (!fs::exists(p, ec)) return std::nullopt;
  return p;
}

std::string command_name() {
  const fs::path exe = executable_path();
  if (exe.empty()) return "pdrt";
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    std::error_code ec;
    const fs::path candidate = fs::path(dir) / exe.filename();
    // The first pdrt on PATH is what "pdrt" runs: it must be this one.
    if (fs::exists(candidate, ec))
      return fs::equivalent(candidate, exe, ec) && !ec ? exe.filename().string() : exe.string();
  }
  return exe.string();
}

}  // namespace pdrt
