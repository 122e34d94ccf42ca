#pragma once
// pbrt-v4's `loopsubdiv` shape: a triangle control mesh refined `levels` times by Loop's
// scheme (Loop 1987) through OpenSubdiv (libosd-dev, Far::TopologyRefiner with SCHEME_LOOP),
// then every vertex moved to the limit surface and given the limit normal, as pbrt-v4's
// LoopSubdivide does. Boundaries follow the smooth boundary-curve rule (pbrt-v4's; OpenSubdiv's
// VTX_BOUNDARY_EDGE_ONLY).
#include "renderer/scene/scene_desc.h"

#include <cstdint>
#include <vector>

namespace pdrt {

// Most triangles a subdivided mesh may have by default (each level multiplies the count by 4):
// a few lines of text ask for 4^levels times their faces, and refinement peaks at about 300
// bytes a triangle (2^22: 1.2 GB; one face at levels 12 would take 4.8 GB).
inline constexpr int64_t kMaxSubdividedTriangles = int64_t(1) << 22;

// positions and triangle indices (3 per face, in range) of the control mesh; levels >= 0.
// Returns the refined mesh with positions, unit normals on the side the control faces' winding
// gives (counter-clockwise), and triangles. Throws InputError (without a location) when
// OpenSubdiv refuses the topology or the result would exceed max_triangles.
MeshData loop_subdivide(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices, int levels,
                        int64_t max_triangles = kMaxSubdividedTriangles);

}  // namespace pdrt
