// `owen-pd`, Owen-scrambled Sobol with the scramble annealed for Poisson-disk prefixes
// (issue 16 item 2; study: stratified-pd.md "owen-opt"): strict (0,m,2)-nets at every power
// of two, and a worst prefix rho >= 0.35 (the study's bar for this family).
#include "sampling/measures/elementary_intervals.h"
#include "sampling/core/errors.h"
#include "sampling/generators/generator.h"
#include "sampling/generators/owen_poisson_2d.h"

#include "tests/support/point_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

namespace pdrt {
namespace {

// One 1024-point table per seed, shared by the tests (each takes ~0.1-0.2 s).
const PointSet& table(uint64_t seed) {
  static std::map<uint64_t, PointSet> cache;
  auto it = cache.find(seed);
  if (it == cache.end()) {
    OwenPoisson2D p;
    p.seed = seed;
    it = cache.emplace(seed, owen_poisson_2d(p)).first;
  }
  return it->second;
}

TEST(OwenPoisson2D, EveryPowerOfTwoPrefixIsA02Net) {
  for (uint64_t seed : {1u, 2u, 3u, 4u}) {
    const std::vector<bool> nets = net_prefixes(table(seed));
    ASSERT_EQ(nets.size(), 11u);
    for (std::size_t m = 0; m < nets.size(); ++m) EXPECT_TRUE(nets[m]) << "seed " << seed << " 2^" << m;
  }
}

// rho = min distance / the hexagonal packing distance sqrt(2 / (sqrt3 n)), over n = 16..1024.
// The study's owen-opt reached 0.409 mean, 0.365 min over 16 seeds; owen-pd measured 0.448
// mean, 0.428 min (seeds 1-16), so 0.35 leaves room for other compilers' rounding of exp/log.
TEST(OwenPoisson2D, EveryPrefixFromSixteenPointsKeepsRhoAboveTheFamilyBar) {
  double worst_all = INFINITY;
  for (uint64_t seed : {1u, 2u, 3u, 4u}) {
    const std::vector<double> d = test::brute_prefix_min_distance(table(seed), true);
    double worst = INFINITY;
    for (std::size_t n = 16; n <= d.size(); ++n)
      worst = std::min(worst, d[n - 1] / std::sqrt(2.0 / (std::sqrt(3.0) * double(n))));
    EXPECT_GE(worst, 0.35) << "seed " << seed;
    worst_all = std::min(worst_all, worst);
  }
  std::printf("owen-pd worst prefix rho (n >= 16, 1024 points, 4 seeds): %.3f\n", worst_all);
}

TEST(OwenPoisson2D, RadiusIsThePrefixMinimumDistance) {
  const PointSet& ps = table(1);
  const std::vector<double> d = test::brute_prefix_min_distance(ps, true);
  ASSERT_EQ(ps.radius.size(), ps.size());
  EXPECT_TRUE(std::isinf(ps.radius[0]));
  for (std::size_t i = 1; i < ps.size(); ++i) ASSERT_NEAR(ps.radius[i], d[i], 1e-12) << i;
}

TEST(OwenPoisson2D, CoordinatesAreOnThe32BitGridInTheUnitSquare) {
  for (double v : table(1).coords) {
    ASSERT_GE(v, 0.0);
    ASSERT_LT(v, 1.0);
    ASSERT_EQ(v * 0x1.0p32, std::floor(v * 0x1.0p32));
  }
}

TEST(OwenPoisson2D, SameSeedGivesIdenticalOutputAndSeedsDiffer) {
  OwenPoisson2D p;
  p.count = 256, p.seed = 9;
  const PointSet a = owen_poisson_2d(p), b = owen_poisson_2d(p);
  EXPECT_EQ(a.coords, b.coords);
  EXPECT_EQ(a.radius, b.radius);
  p.seed = 10;
  EXPECT_NE(owen_poisson_2d(p).coords, a.coords);
}

TEST(OwenPoisson2D, CountNotAPowerOfTwoIsAPrefixOfTheNextPowerOfTwo) {
  OwenPoisson2D p;
  p.count = 1000, p.seed = 1;
  const PointSet part = owen_poisson_2d(p);
  const PointSet& whole = table(1);
  ASSERT_EQ(part.size(), 1000u);
  EXPECT_TRUE(std::equal(part.coords.begin(), part.coords.end(), whole.coords.begin()));
  p.count = 1;
  const PointSet one = owen_poisson_2d(p);
  EXPECT_EQ(one.size(), 1u);
  EXPECT_TRUE(std::isinf(one.radius[0]));
}

TEST(OwenPoisson2D, BadParametersThrowUsageError) {
  auto with = [](auto edit) {
    OwenPoisson2D p;
    p.count = 16;
    edit(p);
    return p;
  };
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.count = 0; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.count = 65537; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.depth = 0; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.depth = 17; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.sweeps = -1; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.beta = 0; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.polish_sweeps = -1; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.polish_beta = NAN; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.temperature = -1; })), UsageError);
  EXPECT_THROW(owen_poisson_2d(with([](OwenPoisson2D& p) { p.level_weight = 5; })), UsageError);
  try {
    owen_poisson_2d(with([](OwenPoisson2D& p) { p.depth = 17; }));
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("depth"), std::string::npos) << e.what();
  }
}

TEST(OwenPoisson2D, GeneratorContractAcceptsOnlyPeriodic2DCounts) {
  GeneratorParams g;
  g.method = "owen-pd", g.dim = 2, g.count = 64, g.seed = 3, g.periodic = true;
  const PointSet ps = generate(g);
  EXPECT_EQ(ps.size(), 64u);
  EXPECT_TRUE(ps.periodic);
  EXPECT_TRUE(ps.has_radius());
  auto rejects = [&](auto edit, const char* word) {
    GeneratorParams bad = g;
    edit(bad);
    try {
      validate(bad);
      ADD_FAILURE() << "accepted: " << word;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  rejects([](GeneratorParams& p) { p.dim = 1; }, "--dim");
  rejects([](GeneratorParams& p) { p.dim = 3; }, "--dim");
  rejects([](GeneratorParams& p) { p.periodic = false; }, "--periodic");
  rejects([](GeneratorParams& p) { p.count = 65537; }, "--count");
  rejects([](GeneratorParams& p) { p.count.reset(), p.radius = 0.01; }, "--radius");
}

}  // namespace
}  // namespace pdrt
