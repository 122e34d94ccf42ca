// GamitoGhostGrid against brute force: a query must hand out every sample (or, on the
// torus, its nearest image) within the reach, whatever the query's place, borders and
// corners included.
#include "sampling/core/distance.h"
#include "sampling/generators/detail/gamito_ghost_grid.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace pdrt {
namespace {

// Dart throwing at distance d: at most one sample per grid cell, as the sampler guarantees.
std::vector<std::array<double, 2>> darts(double d, bool periodic, Rng& rng) {
  std::vector<std::array<double, 2>> pts;
  for (int t = 0; t < 20000; ++t) {
    const std::array<double, 2> p = {rng.uniform(), rng.uniform()};
    bool ok = true;
    for (const auto& q : pts) ok &= distance_sq(p.data(), q.data(), 2, periodic) >= d * d;
    if (ok) pts.push_back(p);
  }
  return pts;
}

void expect_queries_match_brute_force(bool periodic) {
  Rng rng(periodic ? 5 : 6);
  const double d = 0.05, reach = d + 0.5 / std::ceil(std::sqrt(2.0) / d);
  const auto pts = darts(d, periodic, rng);
  ASSERT_GT(pts.size(), 200u);
  GamitoGhostGrid<2> grid(d, periodic, reach);
  for (const auto& p : pts) grid.insert(p.data());
  for (int t = 0; t < 3000; ++t) {
    // Queries all over the square, a third of them on its edges and corners.
    double q[2] = {rng.uniform(), rng.uniform()};
    if (t % 3 == 0) q[t % 2] = (t / 2) % 2 ? 0.0 : std::nextafter(1.0, 0.0);
    std::set<std::size_t> want;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (distance_sq(q, pts[i].data(), 2, periodic) < reach * reach) want.insert(i);
    std::set<std::size_t> got;
    grid.visit(q, reach, [&](const double* s, uint32_t) {
      const double dx = q[0] - s[0], dy = q[1] - s[1];
      if (dx * dx + dy * dy >= reach * reach) return false;
      // Which sample this is (an image differs from it by whole periods).
      for (std::size_t i = 0; i < pts.size(); ++i)
        if (std::abs(std::remainder(s[0] - pts[i][0], 1.0)) < 1e-12 &&
            std::abs(std::remainder(s[1] - pts[i][1], 1.0)) < 1e-12 &&
            (periodic || (s[0] == pts[i][0] && s[1] == pts[i][1])))
          got.insert(i);
      return false;
    });
    ASSERT_EQ(got, want) << "query " << q[0] << ", " << q[1];
  }
}

TEST(GamitoGhostGrid, BoundedQueriesFindEverySampleWithinReach) { expect_queries_match_brute_force(false); }

TEST(GamitoGhostGrid, PeriodicQueriesFindEveryImageWithinReach) { expect_queries_match_brute_force(true); }

TEST(GamitoGhostGrid, VisitCellSeesOnlyOccupiedCells) {
  GamitoGhostGrid<2> grid(0.1, false, 0.2);
  const double p[2] = {0.31, 0.77};
  grid.insert(p);
  int seen = 0;
  grid.visit_cell(grid.cell_of(p), [&](const double* s) { return ++seen, s[0] == p[0] && s[1] == p[1]; });
  const double other[2] = {0.9, 0.1};
  grid.visit_cell(grid.cell_of(other), [&](const double*) { return ++seen, true; });
  EXPECT_EQ(seen, 1);
}

}  // namespace
}  // namespace pdrt
