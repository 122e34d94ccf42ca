// The sample budget of `pdrt compare`: the reference once, every sampler at every spp once per seed.
#include "renderer/compare/compare.h"

#include <gtest/gtest.h>

using namespace pdrt;

TEST(CompareSampleCount, CountsEverySeed) {
  CompareOptions o;
  o.samplers = {"random", "sobol"};
  o.spp = {4, 16};
  o.reference_spp = 64;
  o.seeds = 3;
  EXPECT_DOUBLE_EQ(compare_sample_count(o, 10, 5), (64 + 3 * 2 * (4 + 16)) * 50.0);
  o.adaptive = true;  // the sweep runs seed 0 only: 13 runs per sampler at the largest spp
  EXPECT_DOUBLE_EQ(compare_sample_count(o, 10, 5), (64 + 3 * 2 * (4 + 16) + 13 * 2 * 16) * 50.0);
}
