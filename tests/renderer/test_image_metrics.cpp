// Image error metrics used by `pdrt compare`.
#include "renderer/compare/image_metrics.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

using namespace pdrt;

namespace {
Image noise_image(int w, int h, uint64_t seed, double amplitude) {
  Image im;
  im.width = w, im.height = h;
  Rng rng(seed);
  for (int i = 0; i < 3 * w * h; ++i) im.rgb.push_back(float(0.5 + amplitude * (rng.uniform() - 0.5)));
  return im;
}
}  // namespace

TEST(ImageMetrics, ImageAgainstItselfHasZeroError) {
  Image a = noise_image(32, 24, 1, 0.5);
  EXPECT_EQ(rmse(a, a), 0.0);
  EXPECT_EQ(relative_mse(a, a), 0.0);
  for (double p : error_spectrum(a, a).power) EXPECT_EQ(p, 0.0);
}

TEST(ImageMetrics, RmseOfAConstantOffsetIsTheOffset) {
  Image a = noise_image(16, 16, 2, 0.2), b = a;
  for (float& v : b.rgb) v += 0.25f;
  EXPECT_NEAR(rmse(b, a), 0.25, 1e-6);
}

// White-noise error has a flat spectrum at its variance (Parseval): amplitude^2 / 12 per
// channel, and luminance weights sum to 1 over three independent channels.
TEST(ImageMetrics, WhiteNoiseErrorSpectrumIsFlat) {
  Image a = noise_image(128, 128, 3, 0.0), b = noise_image(128, 128, 4, 1.0);
  RadialSpectrum s = error_spectrum(b, a);
  double w2 = 0.2126 * 0.2126 + 0.7152 * 0.7152 + 0.0722 * 0.0722, expect = w2 / 12;
  double lo = 0, hi = 0;
  for (std::size_t i = 0; i < s.power.size() / 2; ++i) lo += s.power[i];
  for (std::size_t i = s.power.size() / 2; i < s.power.size(); ++i) hi += s.power[i];
  lo /= s.power.size() / 2, hi /= s.power.size() - s.power.size() / 2;
  EXPECT_NEAR(lo, expect, 0.1 * expect);
  EXPECT_NEAR(hi, expect, 0.05 * expect);
}
