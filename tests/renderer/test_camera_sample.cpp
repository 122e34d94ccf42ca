// The camera-sample step: filter offset, time and lens from the pixel's sampler state.
#include "renderer/render/camera_sample.h"

#include <gtest/gtest.h>

#include <memory>

namespace pdrt {
namespace {

FilterDesc filter_desc(FilterType type, float radius, bool rank) {
  FilterDesc d;
  d.type = type;
  d.radius = radius;
  d.rank_selection = rank;
  return d;
}

TEST(CameraSample, DrawsEachDimensionFromItsOwnFamily) {
  // Box of radius 0.5: every sample is taken with weight 1, the film point is the pixel
  // centre plus the scaled Pixel draw, and time and lens are the Time and Lens draws.
  auto sampler = make_sampler("random", 7);
  Filter filter(filter_desc(FilterType::Box, 0.5f, false));
  PixelSampleState ps(*sampler);
  for (int64_t i = 0; i < 64; ++i) {
    CameraSample cs;
    ASSERT_TRUE(get_camera_sample({filter}, 5, 9, i, ps, &cs)) << i;
    Vec2 u = sampler->get_2d(5, 9, i, Family::Pixel, 0);
    EXPECT_EQ(cs.film_x, 5.5f + float(2 * u[0] - 1) * 0.5f) << i;
    EXPECT_EQ(cs.film_y, 9.5f + float(2 * u[1] - 1) * 0.5f) << i;
    EXPECT_EQ(cs.weight, 1.0f) << i;
    EXPECT_EQ(cs.time, float(sampler->get_1d(5, 9, i, Family::Time, 0))) << i;
    EXPECT_EQ(cs.lens, sampler->get_2d(5, 9, i, Family::Lens, 0)) << i;
  }
}

TEST(CameraSample, RankSelectionKeepsSampleWhenItsRankIsBelowTheFilterValue) {
  // Tent filter (min 0): sample i of n is kept exactly when (i + 1) / n <= f / max f, and a
  // kept sample carries f / x = max f.
  auto sampler = make_sampler("random", 3);
  Filter filter(filter_desc(FilterType::Tent, 1.0f, true));
  PixelSampleState ps(*sampler);
  const int n = 256;
  int kept = 0;
  for (int64_t i = 0; i < n; ++i) {
    Vec2 u = sampler->get_2d(2, 1, i, Family::Pixel, 0);
    float x = filter.eval(float(2 * u[0] - 1), float(2 * u[1] - 1)) / filter.max_value();
    CameraSample cs;
    bool taken = get_camera_sample({filter, true, n}, 2, 1, i, ps, &cs);
    EXPECT_EQ(taken, double(i + 1) / n <= x) << i;
    if (taken) {
      EXPECT_FLOAT_EQ(cs.weight, filter.max_value()) << i;
      ++kept;
    }
  }
  EXPECT_GT(kept, 0);
  EXPECT_LT(kept, n);
}

}  // namespace
}  // namespace pdrt
