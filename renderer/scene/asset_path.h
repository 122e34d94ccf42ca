#pragma once
// Where scene files find the assets the build generates (renderer/assetgen/: the procedural
// sky `sky.exr`): $PDRT_ASSETS when set, else the build's assets directory (compiled in).
#include <filesystem>
#include <optional>

namespace pdrt {

// The generated-assets directory, or empty when neither is known.
std::filesystem::path generated_asset_dir();

// `name` relative to the scene's directory if a file is there, else in the generated
// assets; nullopt when neither exists (absolute names: only themselves).
std::optional<std::filesystem::path> find_scene_asset(const std::filesystem::path& scene_dir,
                                                      const std::filesystem::path& name);

}  // namespace pdrt
