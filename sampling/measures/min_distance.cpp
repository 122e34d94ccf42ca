#include "sampling/measures/min_distance.h"

#include "sampling/generators/generator.h"
#include "sampling/measures/kd_tree.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <algorithm>
#include <functional>
#include <limits>

namespace pdrt {

double min_distance(const PointSet& points, bool periodic) {
  const std::size_t n = points.size();
  if (n < 2) return std::numeric_limits<double>::infinity();
  KdTree tree(points.coords, points.dim, periodic);
  double best = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, 1024), std::numeric_limits<double>::infinity(),
      [&](const tbb::blocked_range<std::size_t>& r, double m) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          // Only a neighbour closer than the best so far matters, which keeps searches short.
          auto hit = tree.nearest(&points.coords[i * points.dim], m, uint32_t(i));
          if (hit.id != KdTree::kNone) m = hit.dist_sq;
        }
        return m;
      },
      [](double a, double b) { return std::min(a, b); });
  return std::sqrt(best);
}

double relative_radius(double min_dist, std::size_t count, int dim) {
  if (count < 2) return std::numeric_limits<double>::infinity();
  return min_dist / max_packing_distance(int64_t(count), dim);
}

std::vector<double> prefix_relative_radius(const PointSet& points, bool periodic) {
  const std::size_t n = points.size();
  std::vector<double> rho;
  if (n < 2) return rho;
  rho.reserve(n - 1);
  KdTree tree(points.coords, points.dim, periodic);
  double running_sq = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < n; ++i) {
    // Nearest among points 0..i-1, and only if it beats the running minimum.
    auto hit = tree.nearest(&points.coords[i * points.dim], running_sq, KdTree::kNone, uint32_t(i));
    if (hit.id != KdTree::kNone) running_sq = hit.dist_sq;
    rho.push_back(std::sqrt(running_sq) / max_packing_distance(int64_t(i + 1), points.dim));
  }
  return rho;
}

double worst_prefix_rho(const std::vector<double>& prefix_rho, std::size_t first_n) {
  double worst = std::numeric_limits<double>::infinity();
  for (std::size_t n = std::max<std::size_t>(first_n, 2); n - 2 < prefix_rho.size(); ++n)
    worst = std::min(worst, prefix_rho[n - 2]);
  return worst;
}

}  // namespace pdrt
