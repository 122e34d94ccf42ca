#include "renderer/scene/pbrt/pbrt_build_context.h"

#include "renderer/scene/pbrt/loop_subdivision.h"
#include "renderer/scene/pbrt/ply_mesh.h"
#include "sampling/core/errors.h"

#include <array>
#include <cmath>
#include <filesystem>

// pbrt-v4's shapes as pdrt's: spheres; triangle, bilinear, PLY and Loop-subdivided meshes;
// disks as triangle fans; with the current material or area light, in the scene or in the
// object being defined.

namespace pdrt {
namespace {

// A polygon mesh before it becomes pdrt's: positions, normals, uvs and triangle indices.
struct MeshInput {
  std::vector<Vec3> P, N;
  std::vector<std::array<float, 2>> uvs;
  std::vector<int64_t> idx;
};

void sphere(PbrtBuild& b, const PbrtDirective& d, bool flip, ShapeDesc& s) {
  const PbrtParams& ps = d.params;
  s.kind = ShapeDesc::Kind::Sphere;
  s.radius = b.positive(ps, "radius", 1);
  const double zmin = ps.get_float("zmin", -s.radius), zmax = ps.get_float("zmax", s.radius),
               phimax = ps.get_float("phimax", 360);
  if (zmin > -s.radius || zmax < s.radius || phimax < 360)
    b.note(d.at, "partial spheres are not supported (the whole sphere is used)");
  if (flip && b.gs.cur.area) b.note(d.at, "an inward-facing emitting sphere is not supported (it emits outward)");
}

// Shape "plymesh": the file (relative to the including file) through ply_mesh.h.
MeshInput ply_input(PbrtBuild& b, const PbrtDirective& d) {
  const PbrtParams& ps = d.params;
  std::optional<std::string> name = ps.find_string("filename");
  if (!name) b.fail(d.at, "Shape \"plymesh\" needs \"string filename\"");
  const std::filesystem::path rel =
      d.at.file ? std::filesystem::path(*d.at.file).parent_path() : std::filesystem::path();
  const std::filesystem::path file =
      std::filesystem::path(*name).is_absolute() ? std::filesystem::path(*name) : rel / *name;
  PlyMesh ply;
  try {
    ply = load_ply(file, file.string());
  } catch (const InputError& e) {
    b.fail(ps.find("filename")->at, e.what());
  }
  if (ply.dropped_faces)
    b.note(ps.find("filename")->at,
           std::to_string(ply.dropped_faces) + " points or lines in the PLY file are not surfaces (skipped)");
  MeshInput m;
  m.P = std::move(ply.mesh.positions);
  m.N = std::move(ply.mesh.normals);
  m.uvs = std::move(ply.uvs);
  m.idx.assign(ply.mesh.indices.begin(), ply.mesh.indices.end());
  for (const char* k : {"displacement", "edgelength"})
    if (const PbrtParam* p = ps.find(k)) {
      p->used = true;
      b.note(p->at, std::string("\"") + k + "\" is not supported (ignored)");
    }
  return m;
}

void check_indices(PbrtBuild& b, const PbrtDirective& d, const std::vector<int64_t>& idx, size_t points) {
  for (int64_t i : idx)
    if (i < 0 || uint64_t(i) >= points)
      b.fail(d.params.find("indices") ? d.params.find("indices")->at : d.at,
             "index " + std::to_string(i) + " is out of range [0, " + std::to_string(points - 1) + "]");
}

// "N" and "uv", when given, have one value per point of P.
void check_normal_count(PbrtBuild& b, const PbrtDirective& d, const MeshInput& m) {
  if (!m.N.empty() && m.N.size() != m.P.size())
    b.fail(d.params.find("N") ? d.params.find("N")->at : d.at,
           "\"N\" needs one normal per point (" + std::to_string(m.P.size()) + "), got " + std::to_string(m.N.size()));
}
void check_uv_count(PbrtBuild& b, const PbrtDirective& d, const MeshInput& m) {
  if (!m.uvs.empty() && m.uvs.size() != m.P.size())
    b.fail(d.params.find("uv") ? d.params.find("uv")->at : d.at,
           "\"uv\" needs one per point (" + std::to_string(m.P.size()) + "), got " + std::to_string(m.uvs.size()));
}

// Shape "bilinearmesh": vertices p00 p10 p01 p11 per patch, p(u, v) and uv(u, v) bilinear
// in the patch's (u, v) (uv defaults to (u, v) itself, as pbrt-v4's BilinearPatch). Each patch
// becomes an N x N grid of triangle pairs, N chosen so that position (relative to the patch's
// longest edge) and uv stay within 1e-4 of the patch: a bilinear f = affine + t u v differs
// from its linear interpolation on a grid of step 1/N by at most |t| / (4 N^2). Patches that
// are parallelograms in position and uv are exact at N = 1 (two triangles).
void tessellate_bilinear_patches(PbrtBuild& b, const PbrtDirective& d, MeshInput& m) {
  std::vector<int64_t>& idx = m.idx;
  if (idx.empty() && m.P.size() == 4) idx = {0, 1, 2, 3};
  if (idx.size() % 4) b.fail(d.at, "\"integer indices\" of a bilinearmesh needs a multiple of 4 values");
  check_indices(b, d, idx, m.P.size());
  check_normal_count(b, d, m);
  check_uv_count(b, d, m);
  constexpr int kMaxGrid = 64;
  constexpr double kTolerance = 1e-4;
  // In double, and capped before the conversion to int: a patch of finite corners can still have
  // an infinite twist or size in float (found with fuzz_pbrt: int(NaN) was undefined).
  auto grid_for = [&](double twist, double tol) {
    if (!(twist > 0)) return 1;
    const double g = std::ceil(std::sqrt(twist / (4 * tol)));
    return g >= 1 && g <= kMaxGrid ? int(g) : g < 1 ? 1 : kMaxGrid + 1;
  };
  MeshInput out;
  int64_t capped = 0;
  for (size_t k = 0; k < idx.size(); k += 4) {
    const size_t c[4] = {size_t(idx[k]), size_t(idx[k + 1]), size_t(idx[k + 2]), size_t(idx[k + 3])};
    const Vec3 p[4] = {m.P[c[0]], m.P[c[1]], m.P[c[2]], m.P[c[3]]};
    std::array<float, 2> uv[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    if (!m.uvs.empty())
      for (int i = 0; i < 4; ++i) uv[i] = m.uvs[c[i]];
    const double size = std::max({length(p[1] - p[0]), length(p[2] - p[0]), length(p[3] - p[1]), length(p[3] - p[2])});
    const double twist_p = length(p[0] - p[1] - p[2] + p[3]);
    const double twist_uv = std::max(std::abs(uv[0][0] - uv[1][0] - uv[2][0] + uv[3][0]),
                                     std::abs(uv[0][1] - uv[1][1] - uv[2][1] + uv[3][1]));
    int n = std::max(grid_for(twist_p, kTolerance * size), grid_for(twist_uv, kTolerance));
    if (n > kMaxGrid) n = kMaxGrid, ++capped;
    const int64_t base = int64_t(out.P.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const float u = float(i) / float(n), v = float(j) / float(n);
        const float w[4] = {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
        Vec3 q(0.0f), nn(0.0f);
        std::array<float, 2> t = {0, 0};
        for (int a = 0; a < 4; ++a) {
          q = q + p[a] * w[a];
          t[0] += w[a] * uv[a][0], t[1] += w[a] * uv[a][1];
          if (!m.N.empty()) nn = nn + m.N[c[a]] * w[a];
        }
        out.P.push_back(q);
        out.uvs.push_back(t);
        if (!m.N.empty()) out.N.push_back(length(nn) > 0 ? normalize(nn) : m.N[c[0]]);
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int64_t a = base + j * (n + 1) + i, r = a + 1, up = a + (n + 1), ur = up + 1;
        out.idx.insert(out.idx.end(), {a, r, ur, a, ur, up});  // p00 p10 p11, p00 p11 p01
      }
  }
  if (capped)
    b.note(d.at, std::to_string(capped) + " bilinear patch(es) twisted beyond a " + std::to_string(kMaxGrid) + " x " +
                     std::to_string(kMaxGrid) +
                     " grid of triangles: position or uv there is off the patch by more than 1e-4");
  m = std::move(out);
}

// Shape "loopsubdiv": `levels` Loop refinements to the limit surface (loop_subdivision.h).
void subdivide(PbrtBuild& b, const PbrtDirective& d, MeshInput& in) {
  const PbrtParams& ps = d.params;
  const int64_t levels = ps.get_int("levels", 3);
  if (levels < 0 || levels > 12)
    b.fail(ps.find("levels")->at, "\"integer levels\" must be in [0, 12], got " + std::to_string(levels));
  MeshData m;
  try {
    m = loop_subdivide(in.P, std::vector<uint32_t>(in.idx.begin(), in.idx.end()), int(levels),
                       b.limits.max_subdivided_triangles);
  } catch (const InputError& e) {
    b.fail(d.at, std::string("Shape \"loopsubdiv\": ") + e.what());
  }
  in.P = std::move(m.positions), in.N = std::move(m.normals);
  in.idx.assign(m.indices.begin(), m.indices.end());
}

// The triangles pdrt keeps, degenerate ones dropped. pbrt's geometric normal follows the
// shading normals when there are some, else the winding, reversed by ReverseOrientation and
// by a handedness-swapping transform.
void orient_triangles(const std::vector<int64_t>& idx, bool flip, bool swaps, MeshData& mesh) {
  mesh.indices.reserve(idx.size());
  for (size_t i = 0; i < idx.size(); i += 3) {
    uint32_t a = uint32_t(idx[i]), b = uint32_t(idx[i + 1]), c = uint32_t(idx[i + 2]);
    const Vec3 &pa = mesh.positions[a], &pb = mesh.positions[b], &pc = mesh.positions[c];
    const Vec3 ng = cross(pb - pa, pc - pa);
    if (!(length(ng) > 0)) continue;  // degenerate
    bool swap = flip;
    if (!mesh.normals.empty()) swap = (dot(ng, mesh.normals[a] + mesh.normals[b] + mesh.normals[c]) < 0) != swaps;
    if (swap) std::swap(b, c);
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  }
}

// trianglemesh, loopsubdiv, bilinearmesh, plymesh. False when only degenerate triangles remain
// (reported).
bool mesh(PbrtBuild& b, const PbrtDirective& d, bool flip, ShapeDesc& s) {
  const PbrtParams& ps = d.params;
  const std::string& t = d.strings[0];
  MeshInput m;
  if (t == "plymesh") {
    m = ply_input(b, d);
  } else {
    m.P = ps.point3s("P");
    m.idx = ps.ints("indices");
    if (t != "loopsubdiv") m.N = ps.normal3s("N");
  }
  std::vector<Vec3>& P = m.P;
  std::vector<int64_t>& idx = m.idx;
  if (P.empty()) b.fail(d.at, "Shape \"" + t + "\" needs \"point3 P\"");
  if (t == "trianglemesh" && idx.empty()) {
    if (P.size() != 3)
      b.fail(d.at, "a trianglemesh without \"indices\" must have exactly 3 points, got " + std::to_string(P.size()));
    idx = {0, 1, 2};
  }
  if (t != "plymesh" && t != "loopsubdiv") m.uvs = ps.point2s("uv");
  // Before tessellating bilinear patches, whose grid size is computed from the corners.
  auto check_finite = [&] {
    for (const Vec3& p : P)
      if (!is_finite(p)) b.fail(ps.find("P") ? ps.find("P")->at : d.at, "\"P\" holds a non-finite coordinate");
  };
  check_finite();
  if (t == "bilinearmesh") tessellate_bilinear_patches(b, d, m);
  if (idx.size() % 3)
    b.fail(d.at, "\"integer indices\" needs a multiple of 3 values, got " + std::to_string(idx.size()));
  check_indices(b, d, idx, P.size());
  if (t == "bilinearmesh") check_finite();
  if (t == "loopsubdiv") subdivide(b, d, m);
  const PbrtLocation n_at = ps.find("N") ? ps.find("N")->at : d.at;
  check_normal_count(b, d, m);
  for (Vec3& n : m.N)
    if (!(length(n) > 0) || !is_finite(n)) b.fail(n_at, "\"N\" holds a zero or non-finite normal");
  check_uv_count(b, d, m);
  for (const char* k : {"S", "faceIndices"})
    if (const PbrtParam* p = ps.find(k)) p->used = true;
  s.mesh.positions = std::move(P);
  s.mesh.normals = std::move(m.N);
  s.mesh.uvs = std::move(m.uvs);
  orient_triangles(idx, flip, b.gs.cur.ctm.t[0].det3() < 0, s.mesh);
  if (s.mesh.indices.empty()) {
    b.note(d.at, "the mesh has only degenerate triangles (skipped)");
    return false;
  }
  return true;
}

// Shape "disk": a fan (or ring) of 256 triangles; the polygon's area is 0.01 % below the disk's.
void disk(PbrtBuild& b, const PbrtDirective& d, bool flip, ShapeDesc& s) {
  const PbrtParams& ps = d.params;
  const double h = ps.get_float("height", 0), r = b.positive(ps, "radius", 1),
               ri = b.positive(ps, "innerradius", 0, true);
  if (ps.get_float("phimax", 360) < 360) b.note(d.at, "partial disks are not supported (the whole disk is used)");
  if (!(ri < r)) b.fail(d.at, "\"innerradius\" must be < \"radius\"");
  const int n = 256;
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * kPbrtPi * i / n;
    s.mesh.positions.push_back({float(r * std::cos(phi)), float(r * std::sin(phi)), float(h)});
    if (ri > 0) s.mesh.positions.push_back({float(ri * std::cos(phi)), float(ri * std::sin(phi)), float(h)});
  }
  if (ri == 0) s.mesh.positions.push_back({0, 0, float(h)});
  for (uint32_t i = 0; i < uint32_t(n); ++i) {
    const uint32_t j = (i + 1) % n;
    // Counter-clockwise seen from +z: pbrt's disk faces +z.
    if (ri == 0) {
      s.mesh.indices.insert(s.mesh.indices.end(), {uint32_t(n), i, j});
    } else {
      s.mesh.indices.insert(s.mesh.indices.end(), {2 * i + 1, 2 * i, 2 * j, 2 * i + 1, 2 * j, 2 * j + 1});
    }
  }
  if (flip)
    for (size_t i = 0; i < s.mesh.indices.size(); i += 3) std::swap(s.mesh.indices[i + 1], s.mesh.indices[i + 2]);
}

// The area pbrt-v4's DiffuseAreaLight divides a `power` by: a sphere's and a disk's in object
// space (Sphere::Area, Disk::Area), a triangle's in world space. pbrt-v4 makes every triangle
// of a mesh a light of that power; pdrt's mesh has one radiance, so triangles of unequal area
// get their mean (the same total power, distributed evenly; noted).
double emitter_area(PbrtBuild& b, const PbrtDirective& d, const ShapeDesc& s) {
  const std::string& t = d.strings[0];
  if (t == "sphere") {
    const double r = d.params.get_float("radius", 1);
    return 4 * kPbrtPi * r * r;
  }
  if (t == "disk") {
    const double r = d.params.get_float("radius", 1), ri = d.params.get_float("innerradius", 0);
    return kPbrtPi * (r * r - ri * ri);
  }
  const Affine m = b.gs.cur.ctm.t[0].to_affine();
  double sum = 0, lo = INFINITY, hi = 0;
  const std::vector<Vec3>& p = s.mesh.positions;
  const std::vector<uint32_t>& ix = s.mesh.indices;
  for (size_t i = 0; i + 2 < ix.size(); i += 3) {
    const Vec3 a = m.point(p[ix[i]]), e1 = m.point(p[ix[i + 1]]) - a, e2 = m.point(p[ix[i + 2]]) - a;
    const double area = 0.5 * double(length(cross(e1, e2)));
    sum += area, lo = std::min(lo, area), hi = std::max(hi, area);
  }
  const size_t n = ix.size() / 3;
  if (n > 1 && hi > lo * (1 + 1e-3))
    b.note(d.at,
           "\"power\" of an area light on triangles of unequal area: pbrt-v4 gives each triangle that power, "
           "pdrt gives all of them the radiance of the mean triangle (the same total power)");
  return n ? sum / double(n) : 0;
}

// pbrt-v4's area light shapes also reflect with their material; pdrt's emitters only emit.
void note_emitter_material(PbrtBuild& b, const PbrtDirective& d) {
  if (b.gs.cur.interface) return;  // no surface
  const int i = b.gs.cur.material;
  const Material* m = i >= 0 ? &b.out.scene.materials[size_t(i)] : nullptr;
  if (m && m->type == MaterialType::Diffuse && is_black(m->albedo) && m->textures.empty()) return;
  b.note(d.at,
         "an area light's shape only emits in pdrt; in pbrt-v4 its material (" +
             (m ? "\"" + m->name + "\"" : std::string("the default diffuse 0.5")) +
             ") also reflects the scene's light, so pbrt-v4's emitter is brighter by that",
         "emitter material");
}

// The current area light as an emitter material of its own, else the current material.
void attach_material(PbrtBuild& b, const PbrtDirective& d, ShapeDesc& s) {
  const PbrtAttributes& cur = b.gs.cur;
  if (cur.area && !b.gs.object) {
    Material m;
    m.name = "area light at " + cur.area->at.str();
    m.type = MaterialType::Emitter;
    m.radiance = cur.area->radiance;
    if (cur.area->power) {
      // pbrt-v4 (DiffuseAreaLight::Create): scale *= power / (sides x pi x area).
      const double area = emitter_area(b, d, s);
      const double k = (cur.area->two_sided ? 2 : 1) * kPbrtPi * area;
      m.radiance = k > 0 ? m.radiance * float(*cur.area->power / k) : Vec3(0.0f);
    }
    m.two_sided = cur.area->two_sided;
    note_emitter_material(b, d);
    b.out.scene.materials.push_back(m);
    s.material = int(b.out.scene.materials.size()) - 1;
  } else {
    if (cur.area && b.gs.object) b.note(d.at, "area lights inside object definitions are not supported (no emission)");
    s.material = b.current_material();
  }
}

// Into the object being defined, or into the scene under the CTM.
void add_shape(PbrtBuild& b, const PbrtDirective& d, ShapeDesc s) {
  if (b.gs.object) {
    // pbrt-v4 keeps the whole CTM at the shape's definition (the CTM at ObjectBegin
    // included) as the shape's transform within the object; instances apply theirs on top.
    if (!b.gs.cur.ctm.t[0].affine())
      b.fail(d.at, "the current transform is projective; shapes and lights need an affine one");
    if (b.gs.moving())
      b.note(d.at, "a moving shape inside an object definition is not supported (its start transform is used)");
    s.transform = b.gs.cur.ctm.t[0].to_affine();
    s.where = d.at.str();
    b.out.scene.prototypes[size_t(b.gs.objects[*b.gs.object])].shapes.push_back(std::move(s));
    return;
  }
  b.place(d.at, &s.transform, &s.motion);
  if (!s.motion.empty() &&
      !(b.gs.times[0] >= b.out.scene.camera.shutter_open && b.gs.times[1] <= b.out.scene.camera.shutter_close)) {
    b.note(d.at,
           "motion keys at TransformTimes outside the camera's shutter (the shape's motion is clamped to the shutter)");
  }
  b.out.scene.shapes.push_back(std::move(s));
}

}  // namespace

void translate_pbrt_shape(PbrtBuild& b, const PbrtDirective& d) {
  const PbrtParams& ps = d.params;
  const std::string& t = d.strings[0];
  if (b.gs.cur.interface) {
    for (const PbrtParam& p : ps.list) p.used = true;
    return;  // an interface bounds media only: nothing to see
  }
  if (const PbrtParam* p = ps.find("alpha")) {
    p->used = true;
    b.note(p->at, "\"alpha\" cut-outs are not supported (the shape is opaque)");
  }
  ShapeDesc s;
  s.where = d.at.str();
  const bool flip = b.gs.cur.reverse != (b.gs.cur.ctm.t[0].det3() < 0);
  if (t == "sphere") {
    sphere(b, d, flip, s);
  } else if (t == "trianglemesh" || t == "loopsubdiv" || t == "bilinearmesh" || t == "plymesh") {
    if (!mesh(b, d, flip, s)) return;
  } else if (t == "disk") {
    disk(b, d, flip, s);
  } else {
    b.note(d.at, "Shape \"" + t + "\" is not supported (skipped)");
    for (const PbrtParam& p : ps.list) p.used = true;
    return;
  }
  attach_material(b, d, s);
  add_shape(b, d, std::move(s));
}

}  // namespace pdrt
