// ꟻLIP (renderer/compare/flip.h) against what the papers state and what follows from their
// formulas.
#include "renderer/compare/flip.h"
#include "sampling/core/rng.h"
#include "tests/support/image_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;

namespace {

Image random_image(int w, int h, uint64_t seed, double scale) { return test::random_image(w, h, seed, 0, scale); }

Image flat(int w, int h, float r, float g, float b) { return test::flat_image(w, h, r, g, b); }

// Pixels of the RGB cube's corners and beyond it (HDR values, negative, infinite), in blocks.
Image extreme_image(int w, int h, uint64_t seed) {
  const float values[] = {0.0f, 1.0f, 0.5f, 1000.0f, -3.0f, INFINITY};
  Image im;
  im.width = w, im.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Rng block(seed * 1000 + (y / 4) * 64 + x / 4);
      for (int c = 0; c < 3; ++c) im.rgb.push_back(values[block.next_u64() % 6]);
    }
  return im;
}

void expect_in_unit_interval(const std::vector<float>& map) {
  for (float v : map) {
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
  }
}

}  // namespace

TEST(Flip, IdenticalImagesGiveZeroLdr) {
  const Image a = random_image(24, 20, 1, 1.0);
  for (float v : ldr_flip(a, a)) EXPECT_EQ(v, 0.0f);
}

TEST(Flip, IdenticalImagesGiveZeroHdr) {
  const Image a = random_image(24, 20, 2, 8.0);
  for (float v : hdr_flip(a, a)) EXPECT_EQ(v, 0.0f);
}

// LDR-FLIP is built from |reference - test| terms (HyAB, the feature differences), so it is
// symmetric: swapping the images gives the same map.
TEST(Flip, LdrFlipIsSymmetric) {
  const Image a = random_image(24, 20, 3, 1.0), b = random_image(24, 20, 4, 1.0);
  const std::vector<float> ab = ldr_flip(a, b), ba = ldr_flip(b, a);
  for (std::size_t i = 0; i < ab.size(); ++i) EXPECT_FLOAT_EQ(ab[i], ba[i]);
}

// HDR-FLIP takes its exposures from the reference alone, so it is not symmetric: a dim test
// against a bright reference is judged at the reference's short exposures.
TEST(Flip, HdrFlipIsNotSymmetric) {
  const Image bright = random_image(16, 16, 5, 16.0), dim = random_image(16, 16, 6, 0.25);
  EXPECT_NE(mean_flip(hdr_flip(bright, dim)), mean_flip(hdr_flip(dim, bright)));
}

TEST(Flip, LdrFlipIsInTheUnitIntervalOnRandomAndExtremeImages) {
  expect_in_unit_interval(ldr_flip(random_image(32, 32, 7, 1.0), random_image(32, 32, 8, 1.0)));
  expect_in_unit_interval(ldr_flip(extreme_image(32, 32, 9), extreme_image(32, 32, 10)));
}

TEST(Flip, HdrFlipIsInTheUnitIntervalOnRandomAndExtremeImages) {
  expect_in_unit_interval(hdr_flip(random_image(32, 32, 11, 50.0), random_image(32, 32, 12, 50.0)));
  expect_in_unit_interval(hdr_flip(extreme_image(32, 32, 13), extreme_image(32, 32, 14)));
}

// The colour remap's largest input, c_max, is the HyAB distance of green and blue (the papers'
// choice, the largest over the RGB cube's corners): pure green against pure blue gives 1.
TEST(Flip, GreenAgainstBlueGivesOne) {
  for (float v : ldr_flip(flat(8, 8, 0, 1, 0), flat(8, 8, 0, 0, 1))) EXPECT_NEAR(v, 1.0f, 1e-5);
}

// Black against white: no features in either flat image (dE_f = 0), so FLIP is the remapped
// colour error. HyAB = 100 (L* 0 against 100, a* = b* = 0); 100^0.7 = 25.12 is above
// p_c c_max = 0.4 * 41.28, so it maps into (p_t, 1] = (0.95, 1]: 0.95 + 0.05 (25.12 - 16.51) /
// (41.28 - 16.51) = 0.9674.
TEST(Flip, BlackAgainstWhiteGivesALargeValue) {
  for (float v : ldr_flip(flat(8, 8, 0, 0, 0), flat(8, 8, 1, 1, 1))) EXPECT_NEAR(v, 0.9674f, 1e-3);
}

// The papers' observer model: a one-pixel checkerboard against its mean grey (what it averages
// to far away) differs less when seen from farther (more pixels per degree), since the contrast
// sensitivity filters and the feature detectors widen with the pixels per degree.
TEST(Flip, FineDetailMattersLessFromFarther) {
  Image check = flat(32, 32, 0, 0, 0);
  for (int i = 0; i < 32 * 32; ++i)
    if ((i % 32 + i / 32) % 2)
      for (int c = 0; c < 3; ++c) check.rgb[3 * i + c] = 1.0f;
  const Image grey = flat(32, 32, 0.5f, 0.5f, 0.5f);
  EXPECT_LT(mean_flip(ldr_flip(grey, check, 67.0)), mean_flip(ldr_flip(grey, check, 10.0)));
}

// HDR-FLIP's exposures: c_start = log2(x / Y_max) and c_stop = log2(x / median Y), with T(x) =
// 0.85 for the ACES fit, in max(2, ceil(c_stop - c_start)) steps.
TEST(Flip, HdrExposuresFollowTheReferenceLuminance) {
  Image ref = flat(3, 1, 1, 1, 1);
  for (int c = 0; c < 3; ++c) ref.rgb[3 + c] = 2.0f, ref.rgb[6 + c] = 32.0f;  // Y = 1, 2, 32: median 2
  const FlipExposures e = hdr_flip_exposures(ref);
  EXPECT_NEAR(e.stop - e.start, 4.0, 1e-9);
  EXPECT_EQ(e.count, 4);
  // At the start exposure the brightest pixel tone maps to 0.85.
  EXPECT_NEAR(flip_tone_map(ref, e.start)[6], 0.85f, 1e-5);
  EXPECT_NEAR(flip_tone_map(ref, e.stop)[3], 0.85f, 1e-5);
}
