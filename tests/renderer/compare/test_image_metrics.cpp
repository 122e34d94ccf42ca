// Image error metrics used by `pdrt compare`.
#include "renderer/compare/error_spectrum.h"
#include "renderer/compare/image_metrics.h"
#include "tests/support/image_fixtures.h"

#include <gtest/gtest.h>

using namespace pdrt;

namespace {
// Every channel uniform in 0.5 +- amplitude / 2.
Image noise_image(int w, int h, uint64_t seed, double amplitude) {
  return test::random_image(w, h, seed, 0.5 - amplitude / 2, 0.5 + amplitude / 2);
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

namespace {
Image flat_image(int w, int h, float v) { return test::flat_image(w, h, v, v, v); }
void set_pixel(Image& im, int x, int y, float v) {
  for (int c = 0; c < 3; ++c) im.rgb[3 * (std::size_t(y) * im.width + x) + c] = v;
}
}  // namespace

// A lone pixel 11 times its surroundings is a firefly, one 9 times them is not, and a corner
// pixel counts too (the edge is extended).
TEST(ImageMetrics, FireflyIsAPixelOverTenTimesItsNeighbourhoodMedian) {
  Image im = flat_image(8, 6, 0.1f), ref = flat_image(8, 6, 0.1f);
  set_pixel(im, 3, 2, 1.1f);
  set_pixel(im, 6, 2, 0.9f);
  set_pixel(im, 0, 0, 1.2f);
  const FireflyCount c = count_fireflies(im, ref);
  EXPECT_EQ(c.test, 2);
  EXPECT_EQ(c.reference, 0);
  EXPECT_EQ(c.extra, 2);
}

// A firefly the reference has at the same pixel (a real tiny highlight) is not counted.
TEST(ImageMetrics, FireflyTheReferenceSharesIsNotCounted) {
  Image im = flat_image(8, 6, 0.1f), ref = flat_image(8, 6, 0.1f);
  set_pixel(im, 3, 2, 2.0f);
  set_pixel(ref, 3, 2, 1.5f);
  set_pixel(im, 5, 4, 2.0f);
  const FireflyCount c = count_fireflies(im, ref);
  EXPECT_EQ(c.test, 2);
  EXPECT_EQ(c.reference, 1);
  EXPECT_EQ(c.extra, 1);
}

// A lit pixel on black has a median of 0, so the ratio alone counts it however dim it is; the
// floor asks it to stand out by a visible amount as well.
TEST(ImageMetrics, FireflyFloorDropsDimPixelsOnBlack) {
  Image im = flat_image(8, 6, 0.0f), ref = flat_image(8, 6, 0.0f);
  set_pixel(im, 2, 2, 0.002f);
  set_pixel(im, 5, 3, 0.5f);
  EXPECT_EQ(count_fireflies(im, ref).extra, 2);
  EXPECT_EQ(count_fireflies(im, ref, 10, 0.01).extra, 1);
  EXPECT_EQ(count_fireflies(im, ref, 10, 0.6).extra, 0);
}

// A speck is brighter than ratio x the reference's pixel and above it by more than the floor:
// 4x and +0.3 counts, 2.5x does not, and 4x of a near-black pixel stays under the floor.
TEST(ImageMetrics, SpeckIsAPixelOverRatioTimesTheReferenceAndAboveTheFloor) {
  Image im = flat_image(8, 6, 0.1f), ref = flat_image(8, 6, 0.1f);
  set_pixel(im, 1, 1, 0.4f);
  set_pixel(im, 2, 2, 0.4f);
  // A speck the filter spread over its neighbours: the 3x3 median test misses it.
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (dx || dy) set_pixel(im, 5 + dx, 3 + dy, 0.28f);
  set_pixel(im, 5, 3, 0.4f);
  set_pixel(im, 6, 0, 0.25f);
  set_pixel(ref, 0, 5, 0.001f);
  set_pixel(im, 0, 5, 0.004f);
  EXPECT_EQ(count_fireflies(im, ref, 3).extra, 2);
  EXPECT_EQ(count_specks(im, ref, 3, 0.05), 3);
  EXPECT_EQ(count_specks(im, ref, 3, 0.35), 0);
}

// A sharp edge between dark and bright regions is no firefly: most of a bright edge pixel's
// neighbours are bright.
TEST(ImageMetrics, SharpEdgeIsNoFirefly) {
  Image im = flat_image(8, 8, 0.001f);
  for (int y = 0; y < 8; ++y)
    for (int x = 4; x < 8; ++x) set_pixel(im, x, y, 5.0f);
  EXPECT_EQ(count_fireflies(im, flat_image(8, 8, 0.0f)).test, 0);
}
