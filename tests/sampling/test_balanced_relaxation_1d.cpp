#include "sampling/generators/balanced_relaxation_1d.h"
#include "sampling/analysis/discrepancy.h"
#include "sampling/core/errors.h"
#include "tests/support/point_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace pdrt {
namespace {

PointSet draw(uint64_t seed, int64_t count = 1024, bool periodic = true) {
  BalancedRelaxation1D p;
  p.seed = seed;
  p.count = count;
  p.periodic = periodic;
  return balanced_relaxation_1d(p);
}

class BalancedRelaxation1DDomain : public ::testing::TestWithParam<bool> {};

TEST_P(BalancedRelaxation1DDomain, EveryPrefixHasExactlyItsRecordedRadius) {
  const bool periodic = GetParam();
  PointSet ps = draw(3, 256, periodic);
  ASSERT_EQ(ps.size(), 256u);
  for (std::size_t n = 2; n <= ps.size(); ++n) {
    EXPECT_NEAR(ps.radius[n - 1], test::brute_min_distance(ps, n), 1e-15) << n;  // wrap-around rounding
    EXPECT_LE(ps.radius[n - 1], ps.radius[n - 2]) << n;
  }
  EXPECT_TRUE(test::all_inside_unit_cube(ps));
}

INSTANTIATE_TEST_SUITE_P(PeriodicAndBounded, BalancedRelaxation1DDomain, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "periodic" : "bounded"; });

TEST(BalancedRelaxation1D, PrefixesKeepTheRadiusTargetWhileThereIsRoom) {
  // Every prefix gets min gap >= 0.66/n unless no gap had room (then the largest gap is
  // halved, rarely and mostly in the last 1 %). Issue 3's bar for prefixes of >= 16 points.
  double worst = 1.0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    PointSet ps = draw(seed);
    for (std::size_t n = 16; n <= ps.size(); ++n) worst = std::min(worst, ps.radius[n - 1] * double(n));
  }
  EXPECT_GE(worst, 0.65);
}

TEST(BalancedRelaxation1D, DensityIsEvenAtEveryScale) {
  // Periodic (Kuiper) discrepancy, mean of 8 seeds: measured 0.043 / 0.015 / 0.013 at 64 /
  // 256 / 1024 points. McCool relaxation in 1-D stays at ~0.08; dart throwing has 0.060 /
  // 0.024 / 0.011.
  double mean[3] = {0, 0, 0};
  const std::size_t sizes[3] = {64, 256, 1024};
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    PointSet ps = draw(seed);
    for (int k = 0; k < 3; ++k)
      mean[k] += periodic_discrepancy_1d({ps.coords.begin(), ps.coords.begin() + sizes[k]}) / 8;
  }
  EXPECT_LT(mean[0], 0.055);
  EXPECT_LT(mean[1], 0.02);
  EXPECT_LT(mean[2], 0.02);
}

TEST(BalancedRelaxation1D, SameSeedSamePointsOtherSeedOtherPoints) {
  EXPECT_EQ(draw(7, 300).coords, draw(7, 300).coords);
  EXPECT_NE(draw(7, 300).coords, draw(8, 300).coords);
}

TEST(BalancedRelaxation1D, RefusesAnEmptySet) {
  BalancedRelaxation1D p;
  p.count = 0;
  EXPECT_THROW(balanced_relaxation_1d(p), UsageError);
}

}  // namespace
}  // namespace pdrt
