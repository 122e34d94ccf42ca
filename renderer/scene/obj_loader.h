#pragma once
// Wavefront OBJ (+ MTL) meshes through tinyobjloader, checked more strictly than it checks:
// face indices in range (reported with the OBJ line), MTL libraries and usemtl names that
// exist, finite coordinates. Degenerate triangles are skipped and counted, not errors.
#include "renderer/scene/scene_desc.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace pdrt {

struct ObjPart {
  // From the MTL, named "<obj stem>/<mtl name>" (docs/scene-format.md gives the mapping);
  // "<obj stem>/default" (diffuse) for faces without a material; nullopt when the caller
  // overrides materials.
  std::optional<Material> material;
  MeshData mesh;  // triangles only, object space
};

struct ObjModel {
  std::vector<ObjPart> parts;        // one per material used; no empty meshes
  int64_t degenerate_triangles = 0;  // skipped (repeated vertex, zero area, < 3 vertices)
};

// Throws InputError ("model.obj:17: face index 42 out of range (12 vertices)").
// With override_materials, every face goes into one part without a material.
ObjModel load_obj(const std::filesystem::path& file, bool override_materials);

}  // namespace pdrt
