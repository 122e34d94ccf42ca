// Bridson 2007 in 2-D at scale: the fast path (lattice test, own annulus stream) only runs
// once the radius is below 0.085, i.e. beyond ~100 points, so the generic tests with a few
// hundred points barely reach it. Here it places tens of thousands.
#include "sampling/generators/generator.h"
#include "sampling/measures/min_distance.h"
#include "tests/support/point_checks.h"

#include <gtest/gtest.h>

namespace pdrt {
namespace {

GeneratorParams bridson(bool periodic, double radius, uint64_t seed) {
  GeneratorParams p;
  p.method = "bridson";
  p.dim = 2;
  p.periodic = periodic;
  p.radius = radius;
  p.seed = seed;
  return p;
}

class Bridson2D : public ::testing::TestWithParam<bool> {};

TEST_P(Bridson2D, NoPairCloserThanTheRadius) {
  const bool periodic = GetParam();
  for (uint64_t seed : {1, 2, 3}) {
    PointSet ps = generate(bridson(periodic, 0.004, seed));
    ASSERT_GT(ps.size(), 30000u);
    EXPECT_TRUE(test::all_inside_unit_cube(ps));
    EXPECT_GE(min_distance(ps, periodic), 0.004) << "seed " << seed;
  }
}

TEST_P(Bridson2D, FillsMostOfTheMaximalDensity) {
  // Not maximal (a point retires after k = 30 misses), but close: more than 80% of a
  // maximal set's count (Gamito–Maddock Table I), with walls a little less.
  const bool periodic = GetParam();
  double ratio = double(generate(bridson(periodic, 0.004, 5)).size()) / expected_count_for_radius(0.004, 2);
  EXPECT_LT(ratio, 1.0);
  EXPECT_GT(ratio, periodic ? 0.8 : 0.78);
}

TEST_P(Bridson2D, DeterministicPerSeed) {
  const bool periodic = GetParam();
  EXPECT_EQ(generate(bridson(periodic, 0.01, 9)).coords, generate(bridson(periodic, 0.01, 9)).coords);
  EXPECT_NE(generate(bridson(periodic, 0.01, 9)).coords, generate(bridson(periodic, 0.01, 10)).coords);
}

INSTANTIATE_TEST_SUITE_P(Generators, Bridson2D, ::testing::Bool(),
                         [](const auto& info) { return std::string(info.param ? "periodic" : "bounded"); });

}  // namespace
}  // namespace pdrt
