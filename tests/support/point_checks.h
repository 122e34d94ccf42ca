#pragma once
// Brute-force reference checks shared by the generator tests.
#include "sampling/core/distance.h"
#include "sampling/core/point_set.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pdrt::test {

// Smallest pairwise distance, O(N^2): the reference every faster method is checked against.
inline double brute_min_distance(const PointSet& ps, std::size_t prefix = std::size_t(-1)) {
  std::size_t n = std::min(prefix, ps.size());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      best = std::min(best, distance_sq(ps.point(i), ps.point(j), ps.periodic));
  return std::sqrt(best);
}

inline bool all_inside_unit_cube(const PointSet& ps) {
  return std::all_of(ps.coords.begin(), ps.coords.end(), [](double x) { return x >= 0.0 && x < 1.0; });
}

}  // namespace pdrt::test
