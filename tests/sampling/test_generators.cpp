// Properties every generator promises: domain, minimum distance (brute force), determinism.
#include "sampling/generators/generator.h"
#include "sampling/measures/min_distance.h"
#include "tests/support/point_checks.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace pdrt {
namespace {

using test::all_inside_unit_cube;
using test::brute_min_distance;

GeneratorParams params(const std::string& method, int dim, bool periodic, uint64_t seed = 7) {
  GeneratorParams p;
  p.method = method;
  p.dim = dim;
  p.periodic = periodic;
  p.seed = seed;
  // A few hundred points per run keep the O(N^2) checks and the 3^n-cell grids fast.
  p.count = dim == 1 ? 60 : dim >= 4 ? 150 : 300;
  return p;
}

// (method, dim, periodic) for every Poisson-disk method in 1–5-D.
class PoissonDisk : public ::testing::TestWithParam<std::tuple<std::string, int, bool>> {};

TEST_P(PoissonDisk, AllPointsInsideUnitCube) {
  auto [method, dim, periodic] = GetParam();
  PointSet ps = generate(params(method, dim, periodic));
  ASSERT_GT(ps.size(), 10u);
  EXPECT_TRUE(all_inside_unit_cube(ps));
}

TEST_P(PoissonDisk, NoPairCloserThanSmallestRecordedRadius) {
  auto [method, dim, periodic] = GetParam();
  PointSet ps = generate(params(method, dim, periodic));
  ASSERT_EQ(ps.radius.size(), ps.size());
  double r = *std::min_element(ps.radius.begin(), ps.radius.end());
  EXPECT_GE(brute_min_distance(ps), r * (1 - 1e-12)) << method << " dim " << dim;
}

TEST_P(PoissonDisk, SameSeedGivesSamePoints) {
  auto [method, dim, periodic] = GetParam();
  EXPECT_EQ(generate(params(method, dim, periodic, 11)).coords, generate(params(method, dim, periodic, 11)).coords);
}

TEST_P(PoissonDisk, DifferentSeedGivesDifferentPoints) {
  auto [method, dim, periodic] = GetParam();
  EXPECT_NE(generate(params(method, dim, periodic, 11)).coords, generate(params(method, dim, periodic, 12)).coords);
}

std::string name(const ::testing::TestParamInfo<PoissonDisk::ParamType>& info) {
  std::string m = std::get<0>(info.param);
  std::replace(m.begin(), m.end(), '-', '_');
  return m + "_" + std::to_string(std::get<1>(info.param)) + "D_" + (std::get<2>(info.param) ? "periodic" : "bounded");
}

INSTANTIATE_TEST_SUITE_P(Generators, PoissonDisk,
                         ::testing::Combine(::testing::Values("dart", "mccool", "bridson", "gamito"),
                                            ::testing::Values(1, 2, 3, 4, 5), ::testing::Bool()),
                         name);

// --- McCool–Fiume relaxation: the hierarchical contract -------------------------------

TEST(McCool, ProducesExactlyTheRequestedCount) {
  for (int64_t n : {1, 2, 17, 100, 1000}) {
    GeneratorParams p = params("mccool", 2, false);
    p.count = n;
    EXPECT_EQ(generate(p).size(), std::size_t(n));
  }
}

TEST(McCool, RadiiAreNonIncreasing) {
  PointSet ps = generate(params("mccool", 2, true));
  EXPECT_TRUE(std::is_sorted(ps.radius.rbegin(), ps.radius.rend()));
}

TEST(McCool, EveryPrefixObeysItsRecordedRadius) {
  for (bool periodic : {false, true}) {
    GeneratorParams p = params("mccool", 2, periodic);
    p.count = 400;
    PointSet ps = generate(p);
    // Check a prefix after every radius change: the prefix's minimum distance must
    // be at least the radius in force at its last point.
    for (std::size_t n = 2; n <= ps.size(); ++n)
      if (n == ps.size() || ps.radius[n] != ps.radius[n - 1]) {
        ASSERT_GE(brute_min_distance(ps, n), ps.radius[n - 1] * (1 - 1e-12)) << "prefix " << n;
      }
  }
}

TEST(McCool, PrefixRelativeRadiusStaysHigh) {
  // McCool §4: prefixes stay Poisson-disk; pdrt's bar is rho >= 0.65 for every prefix
  // of >= 16 points (2-D, periodic, 1024 points).
  GeneratorParams p = params("mccool", 2, true, 3);
  p.count = 1024;
  PointSet ps = generate(p);
  double running = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < ps.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j)
      running = std::min(running, std::sqrt(distance_sq(ps.point(i), ps.point(j), true)));
    if (i + 1 >= 16) {
      ASSERT_GE(running / max_packing_distance(int64_t(i + 1), 2), 0.65) << "prefix " << i + 1;
    }
  }
  EXPECT_GE(running / max_packing_distance(1024, 2), 0.72);
}

TEST(McCool, IssueTwoRhoAtFourThousandPoints) {
  // Issue 2's bar at the benchmarked size: 2-D, 4096 points, bounded and periodic, every
  // prefix of >= 16 points rho >= 0.65 and the full set rho >= 0.72 (the pixel tables are
  // made at this scale).
  for (bool periodic : {false, true})
    for (uint64_t seed : {1, 2}) {
      GeneratorParams p = params("mccool", 2, periodic, seed);
      p.count = 4096;
      std::vector<double> rho = prefix_relative_radius(generate(p), periodic);
      ASSERT_EQ(rho.size(), 4095u);
      for (std::size_t n = 16; n <= 4096; ++n)
        ASSERT_GE(rho[n - 2], 0.65) << "prefix " << n << " periodic " << periodic;
      EXPECT_GE(rho.back(), 0.72) << "periodic " << periodic << " seed " << seed;
    }
}

// --- Other methods --------------------------------------------------------------------

TEST(Jitter, OnePointPerGridCell) {
  GeneratorParams p = params("jitter", 2, false);
  p.count = 100;
  PointSet ps = generate(p);
  ASSERT_EQ(ps.size(), 100u);
  std::vector<int> hits(100, 0);
  for (std::size_t i = 0; i < ps.size(); ++i) ++hits[int(ps.point(i)[1] * 10) * 10 + int(ps.point(i)[0] * 10)];
  for (int h : hits) EXPECT_EQ(h, 1);
}

TEST(Jitter, UsesFinestGridThatFitsTheCount) {
  GeneratorParams p = params("jitter", 3, false);
  p.count = 999;  // 9^3 = 729 <= 999 < 1000
  EXPECT_EQ(generate(p).size(), 729u);
}

TEST(Random, ExactCountInsideDomain) {
  GeneratorParams p = params("random", 4, false);
  p.count = 1234;
  PointSet ps = generate(p);
  EXPECT_EQ(ps.size(), 1234u);
  EXPECT_TRUE(all_inside_unit_cube(ps));
  EXPECT_FALSE(ps.has_radius());
}

TEST(Dart, StopsAtTheAttemptBudgetWithFewerPoints) {
  GeneratorParams p = params("dart", 2, true);
  p.count.reset();
  p.radius = 0.1;
  p.attempts = 5;
  PointSet few = generate(p);
  p.attempts = 5000;
  PointSet many = generate(p);
  EXPECT_LT(few.size(), many.size());
  EXPECT_GE(brute_min_distance(many), 0.1);
}

TEST(Bridson, RadiusModeFillsMostOfTheMaximalDensity) {
  // Bridson's method is not maximal (an active point retires after k misses), so it places
  // fewer points than a maximal set at the same radius (Gamito–Maddock Table I, periodic
  // 2-D: packing density 0.547) but, with k = 30, more than 80% of them.
  GeneratorParams p = params("bridson", 2, true);
  p.count.reset();
  p.radius = 0.02;
  double ratio = double(generate(p).size()) / expected_count_for_radius(0.02, 2);
  EXPECT_LT(ratio, 1.0);
  EXPECT_GT(ratio, 0.8);
}

TEST(BestCandidate, EveryPrefixObeysItsRecordedRadius) {
  GeneratorParams p = params("best-candidate", 2, true);
  PointSet ps = generate(p);
  ASSERT_EQ(ps.size(), 300u);
  for (std::size_t i = 1; i < ps.size(); ++i) {
    double nn = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < i; ++j) nn = std::min(nn, std::sqrt(distance_sq(ps.point(i), ps.point(j), true)));
    ASSERT_NEAR(nn, ps.radius[i], 1e-12) << "point " << i;
  }
}

// Mean squared distance from uniform probes to the nearest point: the quantisation error
// that Lloyd's algorithm minimises (McCool §6).
double quantisation_mse(const PointSet& ps) {
  Rng rng(99);
  double sum = 0.0;
  const int probes = 20000;
  for (int s = 0; s < probes; ++s) {
    double q[2] = {rng.uniform(), rng.uniform()};
    double best = 1e9;
    for (std::size_t i = 0; i < ps.size(); ++i)
      best = std::min(best, distance_sq(q, ps.point(i).data(), 2, ps.periodic));
    sum += best;
  }
  return sum / probes;
}

TEST(Lloyd, RelaxationLowersQuantisationError) {
  GeneratorParams p = params("lloyd", 2, true);
  p.lloyd_iterations = 0;
  PointSet start = generate(p);
  p.lloyd_iterations = 10;
  PointSet relaxed = generate(p);
  ASSERT_EQ(relaxed.size(), start.size());
  EXPECT_TRUE(all_inside_unit_cube(relaxed));
  // The hexagonal optimum is 0.0802 A per point (A = cell area); a Poisson-disk start sits
  // a few percent above; ten iterations must remove a measurable part of that excess.
  EXPECT_LT(quantisation_mse(relaxed), 0.99 * quantisation_mse(start));
}

}  // namespace
}  // namespace pdrt
