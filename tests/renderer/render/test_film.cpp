// Film accumulation (renderer/render/film.h): what a pixel keeps of its samples.
#include "renderer/render/film.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace pdrt;

// A NaN or infinite sample is dropped with no weight and counted: the pixel keeps the mean of
// its finite samples instead of being pulled toward black by a zero at full filter weight.
TEST(Film, NonFiniteSamplesAreDroppedWithoutWeightAndCounted) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (Vec3 bad : {Vec3(nan, 0.5f, 0.5f), Vec3(0.5f, inf, 0.5f), Vec3(0.5f, 0.5f, -inf)}) {
    PixelAccum acc;
    acc.add(Vec3(0.5f), 1.0f, Vec3(1.0f), Vec3(0, 0, 1), 2.0f, 0);
    acc.add(bad, 1.0f, Vec3(1.0f), Vec3(0, 0, 1), 2.0f, 1);
    acc.add(Vec3(0.7f), 0.5f, Vec3(1.0f), Vec3(0, 0, 1), 2.0f, 0);
    const Vec3 v = acc.value();
    const float expected = (0.5f * 1.0f + 0.7f * 0.5f) / 1.5f;
    EXPECT_FLOAT_EQ(v.x, expected);
    EXPECT_FLOAT_EQ(v.y, expected);
    EXPECT_FLOAT_EQ(v.z, expected);
    EXPECT_EQ(acc.samples, 2);
    EXPECT_EQ(acc.dropped, 1);
    EXPECT_DOUBLE_EQ(acc.w, 1.5);
    EXPECT_TRUE(std::isfinite(acc.variance_of_mean()));
  }
}
