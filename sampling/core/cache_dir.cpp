#include "sampling/core/cache_dir.h"

#include <cstdlib>

namespace pdrt {

std::filesystem::path cache_dir() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "pdrt";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "pdrt";
  return std::filesystem::temp_directory_path() / "pdrt-cache";
}

}  // namespace pdrt
