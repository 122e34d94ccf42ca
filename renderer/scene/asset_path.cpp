#include "renderer/scene/asset_path.h"

#include "sampling/core/install_paths.h"

#include <cstdlib>

namespace pdrt {
namespace fs = std::filesystem;

fs::path generated_asset_dir() {
  if (const char* env = std::getenv("PDRT_ASSETS"); env && *env) return env;
  if (auto installed = installed_path("share/pdrt/assets")) return *installed;
#ifdef PDRT_BUILD_ASSET_DIR
  return PDRT_BUILD_ASSET_DIR;
#else
  return {};
#endif
}

std::optional<fs::path> find_scene_asset(const fs::path& scene_dir, const fs::path& name) {
  std::error_code ec;
  const fs::path local = scene_dir / name;
  if (fs::is_regular_file(local, ec)) return local;
  if (name.is_absolute()) return std::nullopt;
  const fs::path dir = generated_asset_dir();
  if (dir.empty()) return std::nullopt;
  const fs::path generated = dir / name;
  if (fs::is_regular_file(generated, ec)) return generated;
  return std::nullopt;
}

}  // namespace pdrt
