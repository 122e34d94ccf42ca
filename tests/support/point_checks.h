#pragma once
// Brute-force reference checks shared by the generator tests.
#include "sampling/core/distance.h"
#include "sampling/core/point_set.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pdrt::test {

// Smallest pairwise distance among the first `prefix` points, O(N^2): the reference every
// faster method is checked against. Toroidal when `periodic` (default: the set's own flag).
inline double brute_min_distance(const PointSet& ps, std::size_t prefix, bool periodic) {
  std::size_t n = std::min(prefix, ps.size());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) best = std::min(best, distance_sq(ps.point(i), ps.point(j), periodic));
  return std::sqrt(best);
}
inline double brute_min_distance(const PointSet& ps, std::size_t prefix = std::size_t(-1)) {
  return brute_min_distance(ps, prefix, ps.periodic);
}

// Minimum distance of every prefix: out[i] is that of the first i + 1 points (infinity for
// one point), each point against every earlier one, O(N^2).
inline std::vector<double> brute_prefix_min_distance(const PointSet& ps, bool periodic) {
  std::vector<double> out(ps.size(), std::numeric_limits<double>::infinity());
  double run = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < ps.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) run = std::min(run, distance_sq(ps.point(i), ps.point(j), periodic));
    out[i] = std::sqrt(run);
  }
  return out;
}

inline bool all_inside_unit_cube(const PointSet& ps) {
  return std::all_of(ps.coords.begin(), ps.coords.end(), [](double x) { return x >= 0.0 && x < 1.0; });
}

}  // namespace pdrt::test
