#pragma once
// Minimum distance between points and the relative radius rho of Lagae & Dutré / Gamito–Maddock:
// rho = min distance / the densest-packing distance for the same count (max_packing_distance).
#include "sampling/core/point_set.h"

#include <vector>

namespace pdrt {

// Smallest distance between two distinct points (toroidal when periodic); +inf below 2 points.
// k-d tree nearest-neighbour queries, O(N log N).
double min_distance(const PointSet& points, bool periodic);

// min distance / max_packing_distance(N, dim); +inf below 2 points.
double relative_radius(double min_dist, std::size_t count, int dim);

// rho of every prefix of an ordered set: entry n-2 is the relative radius of the first n points,
// for n = 2..N (empty below 2 points). Incremental: the running minimum only shrinks, and point i
// can shrink it only through its nearest earlier neighbour.
std::vector<double> prefix_relative_radius(const PointSet& points, bool periodic);

// The smallest rho over prefixes of at least `first_n` points, from prefix_relative_radius's
// output (issue 3's bar counts prefixes of >= 16 points); +inf when there are none.
double worst_prefix_rho(const std::vector<double>& prefix_rho, std::size_t first_n);

}  // namespace pdrt
