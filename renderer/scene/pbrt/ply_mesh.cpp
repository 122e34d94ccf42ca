#include "renderer/scene/pbrt/ply_mesh.h"

#include "renderer/scene/input_files.h"
#include "renderer/scene/pbrt/ply_check.h"

#include "sampling/core/errors.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>

namespace pdrt {

PlyMesh load_ply(const std::filesystem::path& file, const std::string& shown) {
  note_input_file(file);
  check_ply(file, shown);  // Assimp 5.2 hangs on some malformed headers and accepts truncated bodies
  Assimp::Importer importer;
  // Only triangulation: the vertices stay as the file has them (no joining, no generated
  // normals), so indices and attributes match pbrt's reading of the same file. The validation
  // runs first and refuses a face whose index is out of range (negative, or past the
  // vertices), which triangulation would read out of bounds (found by fuzz.ply).
  const aiScene* scene = importer.ReadFile(file.string(), aiProcess_ValidateDataStructure | aiProcess_Triangulate);
  if (!scene) {
    std::string why = importer.GetErrorString();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    for (char& c : why)
      if (c == '\n' || c == '\r') c = ' ';
    throw InputError(shown + ": cannot read the PLY mesh: " + why);
  }
  PlyMesh out;
  bool normals = true, uvs = true;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    normals = normals && scene->mMeshes[m]->HasNormals();
    uvs = uvs && scene->mMeshes[m]->HasTextureCoords(0);
  }
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const uint64_t base = out.mesh.positions.size();
    if (base + mesh->mNumVertices > UINT32_MAX)
      throw InputError(shown + ": too many vertices for pdrt (more than 2^32)");
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw InputError(shown + ": vertex " + std::to_string(base + v) + " has a non-finite coordinate");
      out.mesh.positions.push_back({p.x, p.y, p.z});
      if (normals) {
        const aiVector3D& n = mesh->mNormals[v];
        out.mesh.normals.push_back({n.x, n.y, n.z});
      }
      if (uvs) out.uvs.push_back({mesh->mTextureCoords[0][v].x, mesh->mTextureCoords[0][v].y});
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) {
        ++out.dropped_faces;
        continue;
      }
      for (int k = 0; k < 3; ++k) out.mesh.indices.push_back(uint32_t(base + face.mIndices[k]));
    }
  }
  // A normal of zero length (some exporters write them) cannot shade: drop the normals.
  for (const Vec3& n : out.mesh.normals)
    if (!(length(n) > 0) || !is_finite(n)) {
      out.mesh.normals.clear();
      break;
    }
  if (out.mesh.indices.empty()) throw InputError(shown + ": the PLY mesh has no triangles");
  return out;
}

}  // namespace pdrt
