// `stratified-bc`, the 1-D progressive jitter with best-candidate placement (issue 16): exact
// stratification of every power-of-two prefix, and a minimum distance far above jitter's.
#include "sampling/measures/min_distance.h"
#include "sampling/core/errors.h"
#include "sampling/generators/generator.h"
#include "sampling/generators/stratified_best_candidate_1d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace pdrt {
namespace {

PointSet draw(uint64_t seed, int64_t n = 1024, int candidates = 16) {
  StratifiedBestCandidate1D p;
  p.count = n, p.seed = seed, p.candidates = candidates;
  return stratified_best_candidate_1d(p);
}

TEST(StratifiedBestCandidate1D, EveryPowerOfTwoPrefixHasOnePointPerStratum) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const PointSet ps = draw(seed);
    for (int64_t n = 1; n <= 1024; n *= 2) {
      std::vector<int> hits(std::size_t(n), 0);
      for (int64_t i = 0; i < n; ++i) ++hits[std::size_t(ps.coords[std::size_t(i)] * double(n))];
      EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; })) << "seed " << seed << " n " << n;
    }
  }
}

// Every prefix of >= 16 points, brute force (rho = n x min gap on the circle): progressive
// jitter's worst is about 0.02 (docs/sampling.md); the best of 16 candidates keeps it
// above 0.25 on every seed (measured minimum over 8 seeds printed).
TEST(StratifiedBestCandidate1D, EveryPrefixKeepsAMinimumDistanceFarAboveJitters) {
  double worst_all = 1e9;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    const PointSet ps = draw(seed);
    const std::vector<double> rho = prefix_relative_radius(ps, true);
    const double worst = worst_prefix_rho(rho, 16);
    worst_all = std::min(worst_all, worst);
    EXPECT_GT(worst, 0.25) << seed;
    // The recorded radius is the prefix's minimum distance.
    for (std::size_t i = 1; i < ps.size(); ++i) ASSERT_NEAR(ps.radius[i], rho[i - 1] / double(i + 1), 1e-12) << i;
  }
  std::printf("stratified-bc worst prefix rho (n >= 16, 1024 points, 8 seeds): %.3f\n", worst_all);
  EXPECT_TRUE(std::isinf(draw(1, 1).radius[0]));
}

TEST(StratifiedBestCandidate1D, MoreCandidatesRaiseTheMinimumDistanceAndOneIsPlainJitter) {
  double one = 0, many = 0;
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    one += worst_prefix_rho(prefix_relative_radius(draw(seed, 256, 1), true), 16);
    many += worst_prefix_rho(prefix_relative_radius(draw(seed, 256, 64), true), 16);
  }
  EXPECT_GT(many, 4 * one);
}

TEST(StratifiedBestCandidate1D, IsDeterministicAndAvailableThroughTheGeneratorContract) {
  GeneratorParams g;
  g.method = "stratified-bc", g.dim = 1, g.count = 100, g.seed = 7, g.periodic = true;
  const PointSet a = generate(g), b = generate(g);
  EXPECT_EQ(a.coords, b.coords);
  EXPECT_EQ(a.size(), 100u);
  g.dim = 2;
  EXPECT_THROW(generate(g), UsageError);
  StratifiedBestCandidate1D bad;
  bad.candidates = 0;
  EXPECT_THROW(stratified_best_candidate_1d(bad), UsageError);
}

}  // namespace
}  // namespace pdrt
