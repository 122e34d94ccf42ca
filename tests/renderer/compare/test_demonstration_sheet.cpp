// The demonstration sheet of `pdrt compare` and its blurred-error heat maps
// (renderer/compare/demonstration_sheet.h, blurred_heat_maps.h, blurred_error.h).
#include "renderer/compare/blurred_error.h"
#include "renderer/compare/blurred_heat_maps.h"
#include "renderer/compare/demonstration_sheet.h"
#include "renderer/compare/heat_maps.h"
#include "renderer/image/image_output.h"
#include "tests/support/image_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

using namespace pdrt;

namespace {

// A sheet of `samplers` x `spps` cells whose every image is `image` and every error map `error`.
DemoPicture sheet_of(int samplers, int spps, const Image& image, const std::vector<float>& error,
                     const Image& reference, std::array<int, 3> window) {
  DemoInput in;
  in.title = "test";
  for (int r = 0; r < samplers; ++r) in.samplers.push_back("s" + std::to_string(r));
  for (int k = 0; k < spps; ++k) in.spp.push_back(1 << k);
  for (int i = 0; i < samplers * spps; ++i) in.images.push_back(&image), in.errors.push_back(&error);
  in.reference = &reference, in.window = window;
  return demonstration_picture(in);
}

std::array<float, 3> pixel(const DemoPicture& p, int x, int y) {
  const std::size_t i = 3 * (std::size_t(y) * p.layout.width + x);
  return {p.rgb[i], p.rgb[i + 1], p.rgb[i + 2]};
}

const std::array<float, 3> kZeroColour = {kHeatStops[0][0], kHeatStops[0][1], kHeatStops[0][2]};

}  // namespace

// A single-pixel error of `a` in every channel (luminance a: the Rec. 709 weights sum to 1)
// blurred by the sampled, normalised Gaussian of sigma = 1 peaks at a / (sum_d e^{-d^2/2})^2,
// which is a / (2 pi sigma^2) to 3e-6 (the kernel's cut at 4 sigma and the sampling: Poisson
// summation); one pixel away it is e^{-1/2} of the peak; beyond the kernel's radius it is 0.
// Tolerance 1e-4 relative (float sums).
TEST(BlurredErrorMap, SinglePixelImpulseGivesTheAnalyticGaussianPeak) {
  const Image ref = test::random_image(33, 33, 7, 0.2, 0.8);
  Image im = ref;
  const double a = 0.5;
  const std::size_t centre = 3 * (std::size_t(16) * 33 + 16);
  for (int c = 0; c < 3; ++c) im.rgb[centre + c] += float(a);
  const std::vector<float> e = blurred_error_map(im, gaussian_blur(ref, kBlurredMapSigma), kBlurredMapSigma);
  const double peak = a / (2 * std::numbers::pi * kBlurredMapSigma * kBlurredMapSigma);
  EXPECT_NEAR(e[16 * 33 + 16], peak, 1e-4 * peak);
  EXPECT_NEAR(e[16 * 33 + 17], peak * std::exp(-0.5), 1e-4 * peak);
  EXPECT_NEAR(e[17 * 33 + 17], peak * std::exp(-1.0), 1e-4 * peak);
  EXPECT_NEAR(e[16 * 33 + 21], 0.0, 1e-7);  // 5 px away: outside the radius-4 kernel
  EXPECT_NEAR(e[10 * 33 + 16], 0.0, 1e-7);
}

TEST(BlurredErrorMap, ImageEqualToTheReferenceIsAllTheRampsZeroColour) {
  const Image ref = test::random_image(24, 20, 3, 0.0, 2.0);
  const std::vector<float> e = blurred_error_map(ref, gaussian_blur(ref, kBlurredMapSigma), kBlurredMapSigma);
  const std::vector<float> rgb = heat_rgb(e, heat_scale(e));
  ASSERT_EQ(rgb.size(), 3u * 24 * 20);
  for (std::size_t i = 0; i < rgb.size(); ++i) ASSERT_EQ(rgb[i], kZeroColour[i % 3]) << "value " << i;
}

// Width 8 + 104 (labels) + m (2 x 96 + 2 + 10) - 10 + 16 + 96 (reference) + 8; height 8 + 24
// (title) + 20 (header) + n (96 + 6) - 6 + 10 + 18 + 12 + 3 + 14 (colour bar) + 8.
TEST(DemonstrationSheet, PixelSizeFollowsSamplersTimesSpp) {
  const Image ref = test::random_image(128, 128, 1, 0.0, 1.0);
  const std::vector<float> e(128 * 128, 0.01f);
  for (auto [n, m] : {std::array<int, 2>{1, 1}, {5, 4}, {8, 6}, {3, 2}}) {
    const DemoPicture p = sheet_of(n, m, ref, e, ref, {10, 20, 32});  // zoom 3: 96-pixel crops
    EXPECT_EQ(p.layout.zoom, 3);
    EXPECT_EQ(p.layout.width, 222 + 204 * m) << n << " x " << m;
    EXPECT_EQ(p.layout.height, 111 + 102 * n) << n << " x " << m;
    EXPECT_EQ(p.rgb.size(), 3u * std::size_t(p.layout.width) * std::size_t(p.layout.height));
  }
}

TEST(DemonstrationSheet, ImageEqualToTheReferenceGivesTheZeroColourInEveryHeatCrop) {
  const Image ref = test::random_image(40, 30, 5, 0.0, 1.0);
  const std::vector<float> e = blurred_error_map(ref, gaussian_blur(ref, kBlurredMapSigma), kBlurredMapSigma);
  const DemoPicture p = sheet_of(3, 2, ref, e, ref, {4, 6, 16});
  const DemoLayout& l = p.layout;
  ASSERT_EQ(l.zoom, 6);
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 2; ++k) {
      const auto [hx, hy] = l.heat_at(r, k);
      for (int y = 0; y < l.side; ++y)
        for (int x = 0; x < l.side; ++x) ASSERT_EQ(pixel(p, hx + x, hy + y), kZeroColour) << r << "," << k;
      // The image crop beside it: crop pixel (cx, cy) replicated zoom x zoom, sRGB encoded.
      const auto [ix, iy] = l.image_at(r, k);
      const std::size_t src = 3 * (std::size_t(6 + 2) * 40 + 4 + 3);
      EXPECT_EQ(pixel(p, ix + 3 * 6 + 5, iy + 2 * 6),
                (std::array<float, 3>{linear_to_srgb(ref.rgb[src]), linear_to_srgb(ref.rgb[src + 1]),
                                      linear_to_srgb(ref.rgb[src + 2])}));
    }
}

// Cells of errors 1 and 3 share one scale: the 99th percentile of all cells' crop values (3).
TEST(DemonstrationSheet, OneHeatScaleIsSharedByTheWholeSheet) {
  const Image ref = test::flat_image(32, 32, 0.5f, 0.5f, 0.5f);
  const std::vector<float> low(32 * 32, 1.0f), high(32 * 32, 3.0f);
  DemoInput in;
  in.samplers = {"a"}, in.spp = {1, 2};
  in.images = {&ref, &ref}, in.errors = {&high, &low};
  in.reference = &ref, in.window = {0, 0, 32};
  const DemoPicture p = demonstration_picture(in);
  EXPECT_FLOAT_EQ(p.scale, 3.0f);
  const Vec3 third = heat(1.0f / 3);
  const auto [hx, hy] = p.layout.heat_at(0, 1);
  EXPECT_EQ(pixel(p, hx + 5, hy + 5), (std::array<float, 3>{third.x, third.y, third.z}));
}

TEST(DemonstrationSheet, WindowLeavingTheImageIsRefused) {
  const Image ref = test::random_image(32, 32, 2, 0.0, 1.0);
  const std::vector<float> e(32 * 32, 0.0f);
  EXPECT_THROW(sheet_of(1, 1, ref, e, ref, {20, 0, 16}), std::invalid_argument);
  EXPECT_THROW(sheet_of(1, 1, ref, e, ref, {-1, 0, 8}), std::invalid_argument);
  EXPECT_THROW(sheet_of(1, 1, ref, e, ref, {0, 0, 0}), std::invalid_argument);
}

TEST(DemonstrationSheet, DrawnUpToEightSamplersAndSixSampleCounts) {
  CompareOptions o;
  o.samplers = {"a", "b", "c", "d", "e", "f", "g", "h"}, o.spp = {1, 2, 4, 8, 16, 32};
  EXPECT_TRUE(demonstration_drawn(o));
  o.spp.push_back(64);
  EXPECT_FALSE(demonstration_drawn(o));
  o.spp.pop_back(), o.samplers.push_back("i");
  EXPECT_FALSE(demonstration_drawn(o));
}
