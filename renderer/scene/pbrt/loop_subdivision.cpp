#include "renderer/scene/pbrt/loop_subdivision.h"

#include "sampling/core/errors.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>

namespace pdrt {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// A vertex as OpenSubdiv's PrimvarRefiner wants it: Clear and AddWithWeight.
struct Point {
  double x = 0, y = 0, z = 0;
  void Clear(void* = nullptr) { x = y = z = 0; }
  void AddWithWeight(const Point& p, float w) { x += w * p.x, y += w * p.y, z += w * p.z; }
  void AddWithWeight(const Point& p, double w) { x += w * p.x, y += w * p.y, z += w * p.z; }
};

Vec3 cross_d(const Point& a, const Point& b, double* len) {
  const double cx = a.y * b.z - a.z * b.y, cy = a.z * b.x - a.x * b.z, cz = a.x * b.y - a.y * b.x;
  *len = std::sqrt(cx * cx + cy * cy + cz * cz);
  return {float(cx), float(cy), float(cz)};
}

}  // namespace

MeshData loop_subdivide(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices, int levels,
                        int64_t max_triangles) {
  const int64_t faces = int64_t(indices.size() / 3);
  if (levels > 0 && faces > (max_triangles >> std::min(2 * levels, 62)))
    throw InputError(std::to_string(faces) + " triangles subdivided " + std::to_string(levels) + " times exceed " +
                     std::to_string(max_triangles) + " triangles");
  std::vector<int> per_face(size_t(faces), 3);
  std::vector<Far::Index> verts(indices.begin(), indices.end());
  Far::TopologyDescriptor desc;
  desc.numVertices = int(positions.size());
  desc.numFaces = int(faces);
  desc.numVertsPerFace = per_face.data();
  desc.vertIndicesPerFace = verts.data();

  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(Sdc::SCHEME_LOOP, options)));
  if (!refiner) throw InputError("OpenSubdiv cannot build the control mesh's topology");
  if (levels > 0) {
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uniform);
  }

  // Interpolate level by level, then evaluate the limit at the last level's vertices.
  std::vector<Point> level(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) level[i] = {positions[i].x, positions[i].y, positions[i].z};
  Far::PrimvarRefiner primvar(*refiner);
  for (int l = 1; l <= levels; ++l) {
    std::vector<Point> next(size_t(refiner->GetLevel(l).GetNumVertices()));
    Point* dst = next.data();
    primvar.Interpolate(l, level.data(), dst);
    level = std::move(next);
  }
  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  std::vector<Point> limit(level.size()), du(level.size()), dv(level.size());
  {
    Point *p = limit.data(), *a = du.data(), *b = dv.data();
    primvar.Limit(level.data(), p, a, b);
  }

  MeshData out;
  out.positions.reserve(limit.size());
  for (const Point& p : limit) out.positions.push_back({float(p.x), float(p.y), float(p.z)});
  out.indices.reserve(size_t(last.GetNumFaces()) * 3);
  std::vector<Vec3> face_sum(limit.size(), Vec3(0.0f));
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    Far::ConstIndexArray fv = last.GetFaceVertices(f);
    const uint32_t a = uint32_t(fv[0]), b = uint32_t(fv[1]), c = uint32_t(fv[2]);
    out.indices.insert(out.indices.end(), {a, b, c});
    const Vec3 n = cross(out.positions[b] - out.positions[a], out.positions[c] - out.positions[a]);
    face_sum[a] += n, face_sum[b] += n, face_sum[c] += n;
  }
  // The limit tangents' cross product, turned to the winding's side (OpenSubdiv's tangent
  // order does not promise it); where the limit tangents degenerate, the faces' mean.
  out.normals.resize(limit.size());
  for (size_t i = 0; i < limit.size(); ++i) {
    double len = 0;
    Vec3 n = cross_d(du[i], dv[i], &len);
    if (!(len > 0) || !std::isfinite(len)) n = face_sum[i];
    if (dot(n, face_sum[i]) < 0) n = -n;
    const float l = length(n);
    out.normals[i] = l > 0 ? n / l : Vec3(0, 0, 1);
  }
  return out;
}

}  // namespace pdrt
