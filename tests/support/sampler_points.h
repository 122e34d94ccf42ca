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

// Values first <= i < n of a (pixel, family, bounce) stream whose prepared form
// (Sampler::prepare of the window [first, n)) differs from get_1d / get_2d, bit for bit; -1
// when nothing was prepared or the window was not.
inline int prepared_mismatches(const Sampler& s, int px, int py, Family f, int bounce, uint32_t n, uint32_t first = 0) {
  PreparedStream p;
  p.first = first, p.want = n;
  s.prepare(px, py, f, bounce, &p);
  if (!p.coords || p.count < n || p.base > first) return -1;
  int bad = 0;
  for (uint32_t i = first; i < n; ++i) {
    if (family_dim(f) == 1) {
      bad += p.value(i, 0) != s.get_1d(px, py, i, f, bounce);
    } else {
      const Vec2 v = s.get_2d(px, py, i, f, bounce);
      bad += p.value(i, 0) != v[0] || p.value(i, 1) != v[1];
    }
  }
  return bad;
}

}  // namespace pdrt::test
