#pragma once
// Writes a SceneDesc as a pdrt scene JSON file (docs/scene-format.md) that loads back into the
// same description: `pdrt convert` (a pbrt-v4 scene, say) into pdrt's own format, so users can
// edit it there. Triangle meshes go to OBJ files in a folder beside the JSON
// (`NAME.meshes/shapeI.obj`, positions, normals and uvs at full float precision); materials and
// textures get short generated names (m0, m1, ..., t0, t1, ...). Every file is written
// atomically: a failure leaves no half-written output.
#include "renderer/scene/scene_desc.h"

#include <filesystem>

namespace pdrt {

struct SceneWriteOptions {
  // Triangle meshes written into the JSON itself (`"type": "mesh"` with vertices, normals,
  // uvs, indices) instead of OBJ files: one self-contained file, for small scenes and tests.
  bool inline_meshes = false;
};

// Throws InputError (what cannot be written, or what the format cannot say) naming the file.
void write_scene_json(const SceneDesc& scene, const std::filesystem::path& json_file,
                      const SceneWriteOptions& options = {});

}  // namespace pdrt
