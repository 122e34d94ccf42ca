// pbrt's loopsubdiv through OpenSubdiv (renderer/scene/pbrt/loop_subdivision.h): the refined
// mesh's size, Loop's limit positions from his published masks (computed here independently
// of OpenSubdiv), the boundary's cubic B-spline limit, planarity, affine invariance and the
// normals' side.
#include "renderer/scene/pbrt/loop_subdivision.h"
#include "sampling/core/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;

namespace {

// The octahedron of unit radius, faces counter-clockwise seen from outside.
void octahedron(std::vector<Vec3>* p, std::vector<uint32_t>* idx) {
  *p = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  *idx = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
}

// Loop's limit mask for an interior vertex of valence n: (1 - n chi) p + chi sum(q),
// chi = 1 / (n + 3 / (8 beta)), beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n (Loop 1987).
double loop_chi(int n) {
  const double c = 3.0 / 8 + std::cos(2 * M_PI / n) / 4;
  const double beta = (5.0 / 8 - c * c) / n;
  return 1 / (n + 3 / (8 * beta));
}

}  // namespace

TEST(LoopSubdivision, EachLevelQuadruplesTheFacesOfAClosedMesh) {
  std::vector<Vec3> p;
  std::vector<uint32_t> idx;
  octahedron(&p, &idx);
  // V' = V + E, F' = 4 F; the octahedron has V 6, E 12, F 8.
  const int v[] = {6, 18, 66, 258}, f[] = {8, 32, 128, 512};
  for (int level = 0; level <= 3; ++level) {
    MeshData m = loop_subdivide(p, idx, level);
    EXPECT_EQ(m.positions.size(), size_t(v[level])) << "level " << level;
    EXPECT_EQ(m.indices.size(), size_t(3 * f[level])) << "level " << level;
    EXPECT_EQ(m.normals.size(), m.positions.size());
  }
}

TEST(LoopSubdivision, ControlVerticesMoveToLoopsLimitPositions) {
  std::vector<Vec3> p;
  std::vector<uint32_t> idx;
  octahedron(&p, &idx);
  // Valence 4, neighbours summing to 0: the limit is (1 - 4 chi) p.
  const double expect = 1 - 4 * loop_chi(4);
  MeshData m = loop_subdivide(p, idx, 0);
  for (int i = 0; i < 6; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.positions[i][c], expect * p[i][c], 1e-6) << "vertex " << i;
  // Refining first does not move the limit: control vertex 0 keeps its index at every level.
  MeshData m3 = loop_subdivide(p, idx, 3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(m3.positions[0][c], expect * p[0][c], 1e-5);
}

TEST(LoopSubdivision, AFanConvergesToTheBoundarySplineAndTheInteriorMask) {
  // An irregular hexagon around an off-centre point, far from the origin: the centre is an
  // interior vertex of valence 6 (chi = 1/12), the rim vertices lie on the boundary, whose
  // limit is the cubic B-spline's (p_prev + 4 p + p_next) / 6.
  const Vec3 o(1e3f, -2e3f, 5e2f);
  std::vector<Vec3> p = {o + Vec3(0.1f, -0.2f, 0)};
  for (int i = 0; i < 6; ++i) {
    const double a = i * M_PI / 3, r = 1 + 0.3 * (i % 3);
    p.push_back(o + Vec3(float(r * std::cos(a)), float(r * std::sin(a)), 0));
  }
  std::vector<uint32_t> idx;
  for (uint32_t i = 0; i < 6; ++i) idx.insert(idx.end(), {0, 1 + i, 1 + (i + 1) % 6});
  MeshData m = loop_subdivide(p, idx, 0);
  Vec3 ring(0.0f);
  for (int i = 1; i <= 6; ++i) ring += p[i] - o;
  const Vec3 centre = (p[0] - o) * float(1 - 6 * loop_chi(6)) + ring * float(loop_chi(6));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.positions[0][c] - o[c], centre[c], 2e-4) << c;
  for (int i = 1; i <= 6; ++i) {
    const Vec3 prev = p[1 + (i + 4) % 6] - o, next = p[1 + i % 6] - o;
    const Vec3 expect = (prev + (p[i] - o) * 4.0f + next) / 6.0f;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.positions[i][c] - o[c], expect[c], 2e-4) << "rim vertex " << i;
  }
  // A planar mesh stays in its plane, its normals +z (the fan is counter-clockwise seen from +z).
  MeshData m2 = loop_subdivide(p, idx, 2);
  for (size_t i = 0; i < m2.positions.size(); ++i) {
    EXPECT_EQ(m2.positions[i].z, o.z);
    EXPECT_NEAR(m2.normals[i].z, 1, 1e-6) << i;
  }
}

TEST(LoopSubdivision, CommutesWithAffineMapsAndNormalsPointOutward) {
  std::vector<Vec3> p;
  std::vector<uint32_t> idx;
  octahedron(&p, &idx);
  auto map = [](const Vec3& v) { return Vec3(2 * v.x + 0.5f * v.y + 3, -v.y + 1e-3f, 0.25f * v.z - 7); };
  std::vector<Vec3> q;
  for (const Vec3& v : p) q.push_back(map(v));
  MeshData a = loop_subdivide(p, idx, 2), b = loop_subdivide(q, idx, 2);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (size_t i = 0; i < a.positions.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(map(a.positions[i])[c], b.positions[i][c], 1e-5) << i;
  // The octahedron's limit surface is convex and centred: every normal points away from 0.
  for (size_t i = 0; i < a.positions.size(); ++i) {
    EXPECT_NEAR(length(a.normals[i]), 1, 1e-5);
    EXPECT_GT(dot(a.normals[i], a.positions[i]), 0.5f * length(a.positions[i])) << i;
  }
  // Reversing the winding turns every normal inward.
  std::vector<uint32_t> rev = idx;
  for (size_t i = 0; i < rev.size(); i += 3) std::swap(rev[i + 1], rev[i + 2]);
  MeshData r = loop_subdivide(p, rev, 2);
  for (size_t i = 0; i < r.normals.size(); ++i)
    EXPECT_LT(dot(r.normals[i], r.positions[i]), -0.5f * length(r.positions[i])) << i;
}

TEST(LoopSubdivision, RefusesMoreTrianglesThanTheLimit) {
  std::vector<Vec3> p;
  std::vector<uint32_t> idx;
  octahedron(&p, &idx);
  EXPECT_THROW(loop_subdivide(p, idx, 10), InputError);  // 8 * 4^10 > 2^22
  EXPECT_THROW(loop_subdivide(p, idx, 2, 8 * 16 - 1), InputError);
  EXPECT_EQ(loop_subdivide(p, idx, 2, 8 * 16).indices.size(), size_t(3 * 8 * 16));
}
