// `stratified-pd`, the "(0,2)-first" hierarchical Poisson-disk sequence (issue 16): the rho
// floor on every prefix (brute force), the strata it keeps, and its (0,2) core.
#include "sampling/measures/elementary_intervals.h"
#include "sampling/measures/min_distance.h"
#include "sampling/core/errors.h"
#include "sampling/generators/generator.h"
#include "sampling/generators/stratified_poisson_2d.h"

#include "tests/support/point_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace pdrt {
namespace {

PointSet draw(uint64_t seed, int64_t n, double prefix_floor = 0.65, double whole_floor = 0.72) {
  StratifiedPoisson2D p;
  p.count = n, p.seed = seed, p.prefix_floor = prefix_floor, p.whole_floor = whole_floor;
  return stratified_poisson_2d(p);
}

TEST(StratifiedPoisson2D, EveryPrefixKeepsTheFloorAndTheWholeSetItsBar) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const PointSet ps = draw(seed, 1024);
    const auto m = test::brute_prefix_min_distance(ps, true);
    for (std::size_t n = 16; n <= ps.size(); ++n)
      ASSERT_GE(m[n - 1] / max_packing_distance(int64_t(n), 2), 0.65) << "seed " << seed << " prefix " << n;
    EXPECT_GE(m.back() / max_packing_distance(1024, 2), 0.72) << seed;
    // The recorded radius is the prefix's minimum distance.
    for (std::size_t i = 1; i < ps.size(); ++i) ASSERT_DOUBLE_EQ(ps.radius[i], m[i]) << i;
  }
}

// Without a floor nothing forces a stratum open: every power-of-two prefix is a (0,m,2)-net
// (the candidates are the cells every elementary interval leaves free).
TEST(StratifiedPoisson2D, WithoutAFloorEveryPowerOfTwoPrefixIsANet) {
  for (uint64_t seed : {1u, 2u}) {
    const PointSet ps = draw(seed, 1024, 0.0, 0.0);
    for (std::size_t n = 1; n <= 1024; n *= 2) EXPECT_TRUE(is_02_net(ps, 0, n)) << "seed " << seed << " n " << n;
    EXPECT_EQ(stratum_breaks(ps), 0u);
  }
}

// The floor opens only the strata it must: measured 667 of 2048 points at floor 0.5 and
// 1530 at 0.65 (stratified-pd.md: 30-70 %); pure best candidate would break nearly all.
TEST(StratifiedPoisson2D, TheFloorBreaksStrataOnlyWhereItMust) {
  const std::size_t low = stratum_breaks(draw(4, 1024, 0.5, 0.5)), high = stratum_breaks(draw(4, 1024));
  EXPECT_LT(low, high);
  EXPECT_LT(high, 900u);  // of 1024
  // The first 16 points stay stratified by squares: 4 x 4 strata, one point each.
  const PointSet ps = draw(4, 1024);
  std::vector<int> hits(16, 0);
  for (int i = 0; i < 16; ++i) ++hits[std::size_t(int(ps.coords[2 * i] * 4) * 4 + int(ps.coords[2 * i + 1] * 4))];
  for (int h : hits) EXPECT_EQ(h, 1);
}

TEST(StratifiedPoisson2D, IsDeterministicInItsSeedAndExactFixedPoint) {
  const PointSet a = draw(9, 512), b = draw(9, 512), c = draw(10, 512);
  EXPECT_EQ(a.coords, b.coords);
  EXPECT_NE(a.coords, c.coords);
  for (double x : a.coords) EXPECT_EQ(x, std::ldexp(std::floor(std::ldexp(x, 32)), -32));
}

TEST(StratifiedPoisson2D, RefusesBadParameters) {
  StratifiedPoisson2D p;
  p.count = 0;
  EXPECT_THROW(stratified_poisson_2d(p), UsageError);
  p.count = 16, p.candidates = 0;
  EXPECT_THROW(stratified_poisson_2d(p), UsageError);
  p.candidates = 8, p.prefix_floor = 1.5;
  EXPECT_THROW(stratified_poisson_2d(p), UsageError);
  GeneratorParams g;
  g.method = "stratified-pd", g.dim = 3, g.count = 16;
  EXPECT_THROW(generate(g), UsageError);
}

TEST(StratifiedPoisson2D, IsAGeneratorMethod) {
  GeneratorParams g;
  g.method = "stratified-pd", g.dim = 2, g.count = 256, g.seed = 3, g.periodic = true;
  const PointSet ps = generate(g);
  ASSERT_EQ(ps.size(), 256u);
  EXPECT_GE(worst_prefix_rho(prefix_relative_radius(ps, true), 16), 0.65);
}

}  // namespace
}  // namespace pdrt
