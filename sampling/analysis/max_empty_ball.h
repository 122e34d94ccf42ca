#pragma once
// Coverage: the largest ball centred in the domain [0,1]^dim that holds no sample, i.e. the
// maximum over the domain of the distance to the nearest sample. A Poisson-disk set with
// minimum distance r (pdrt's "radius") is maximal exactly when this radius is <= r: no
// further point could be placed.
#include "sampling/core/point_set.h"

#include <string>
#include <vector>

namespace pdrt {

struct EmptyBall {
  double radius = 0.0;         // distance from `center` to the nearest sample
  std::vector<double> center;  // in [0,1]^dim (wrapped into [0,1) when periodic)
  std::string method;          // "exact-1d", "voronoi-2d" or "probe-ascent"
  bool exact = false;          // false: a lower bound from probing plus local ascent
  std::size_t probes = 0;      // probe-ascent only
};

// 1-D: largest gap (exact). 2-D: exact, from the Voronoi vertices (cells clipped cell by cell,
// with the domain boundary when not periodic). 3-D and up: dense random probes, the best of
// which climb to a local maximum of the nearest-sample distance (a Voronoi vertex).
EmptyBall max_empty_ball(const PointSet& points, bool periodic, uint64_t seed = 1);

}  // namespace pdrt
