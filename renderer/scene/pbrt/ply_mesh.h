#pragma once
// PLY meshes (binary and ASCII; positions, normals, texture coordinates, triangles and
// polygons) read through Assimp, the maintained Debian library (libassimp-dev), for pbrt-v4's
// "plymesh" shape. Polygons are triangulated; points and lines are dropped.
#include "renderer/scene/scene_desc.h"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

struct PlyMesh {
  MeshData mesh;                          // positions, normals (per vertex, or empty), triangles
  std::vector<std::array<float, 2>> uvs;  // per vertex, or empty
  int64_t dropped_faces = 0;              // points and lines
};

// Throws InputError "<shown>: <Assimp's reason>" when the file cannot be read or holds no
// triangles; `shown` names the file as the scene did.
PlyMesh load_ply(const std::filesystem::path& file, const std::string& shown);

}  // namespace pdrt
