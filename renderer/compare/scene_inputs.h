#pragma once
// The content of every file a scene depends on, as text for compare's reference cache key and
// the plan's scene hash: a mesh, texture, included file or environment image edited gives a new
// key, so a reference cached for the old scene is never reused (issue 29).
#include "renderer/scene/scene_desc.h"

#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

// One "|<file name> <bytes> <fnv1a>" entry per file of `read` (what the load read, except
// `scene.file` itself) and per image texture of `scene`, in that order; a file that cannot be
// read is "|<file name> unreadable".
std::string scene_inputs_text(const SceneDesc& scene, const std::vector<std::filesystem::path>& read);

}  // namespace pdrt
