#pragma once
// The 2-D values a sampler gives pixels, as a point set for the point-set checks.
#include "sampling/core/point_set.h"
#include "sampling/samplers/sampler.h"

#include <array>
#include <vector>

namespace pdrt::test {

// Samples 0 .. n-1 of `family` at `bounce` of each pixel in turn.
inline PointSet stream_points(const Sampler& s, const std::vector<std::array<int, 2>>& pixels, int n, Family family,
                              int bounce) {
  PointSet ps;
  ps.dim = 2;
  for (auto [x, y] : pixels)
    for (int i = 0; i < n; ++i) {
      const Vec2 v = s.get_2d(x, y, i, family, bounce);
      ps.coords.push_back(v[0]);
      ps.coords.push_back(v[1]);
    }
  return ps;
}

}  // namespace pdrt::test
