// The blurred error of `pdrt compare` (renderer/compare/blurred_error.h).
#include "renderer/compare/blurred_error.h"
#include "tests/support/image_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;

namespace {

// Every channel uniform in +- amplitude / 2.
Image uniform_noise(int w, int h, uint64_t seed, double amplitude) {
  return test::random_image(w, h, seed, -amplitude / 2, amplitude / 2);
}

// The RMS of `im` over the pixels at least `margin` from every edge, where the kernel is whole.
double interior_mean_square(const Image& im, int margin) {
  double s = 0;
  long n = 0;
  for (int y = margin; y < im.height - margin; ++y)
    for (int x = margin; x < im.width - margin; ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = im.rgb[3 * (std::size_t(y) * im.width + x) + c];
        s += v * v, ++n;
      }
  return s / double(n);
}

// White noise of standard deviation s blurred by a normalised Gaussian of sigma pixels has
// standard deviation s sqrt(sum w^2) = s / (2 sqrt(pi) sigma) (the sampled Gaussian's sum of
// squares matches the integral to 1e-4 for sigma >= 1). Over 64 images of 64x64 the interior
// RMS has a relative standard error of about 1.3 % at sigma = 2 (the blur leaves about
// 64 * 48^2 / (4 pi sigma^2) independent values), 0.6 % at sigma = 1; tolerance 5 %.
void expect_white_noise_blur(double sigma) {
  const double amplitude = 1.0, s = amplitude / std::sqrt(12.0);
  const int margin = int(std::ceil(4 * sigma));
  double ms = 0;
  for (int k = 0; k < 64; ++k)
    ms += interior_mean_square(gaussian_blur(uniform_noise(64, 64, 100 + k, amplitude), sigma), margin) / 64;
  const double expect = s / (2 * std::sqrt(M_PI) * sigma);
  EXPECT_NEAR(std::sqrt(ms), expect, 0.05 * expect) << "sigma " << sigma;
}

}  // namespace

TEST(BlurredError, ConstantErrorKeepsItsValue) {
  const Image ref = uniform_noise(32, 24, 1, 1.0);
  Image test = ref;
  for (float& v : test.rgb) v += 0.25f;
  for (double sigma : kBlurSigmas) EXPECT_NEAR(blurred_rmse(test, ref, sigma), 0.25, 1e-5) << "sigma " << sigma;
}

// The kernel is renormalised over the pixels inside the image, so a constant image stays that
// constant up to its corners.
TEST(BlurredError, ConstantImageStaysConstantAtTheEdges) {
  Image im;
  im.width = 9, im.height = 7;
  im.rgb.assign(3 * 9 * 7, 0.7f);
  for (float v : gaussian_blur(im, 2.0).rgb) EXPECT_NEAR(v, 0.7f, 1e-6);
}

TEST(BlurredError, WhiteNoiseAtSigmaOneMatchesTheAnalyticSpread) { expect_white_noise_blur(1.0); }

TEST(BlurredError, WhiteNoiseAtSigmaTwoMatchesTheAnalyticSpread) { expect_white_noise_blur(2.0); }

// A one-pixel checkerboard error (the highest frequency) nearly vanishes under the blur: its
// Gaussian transfer at (0.5, 0.5) cycles per pixel is exp(-2 pi^2 sigma^2 0.5) = 5e-5 at sigma 1;
// only the edges' renormalised kernels leave a little.
TEST(BlurredError, CheckerboardErrorIsBlurredAway) {
  Image ref = uniform_noise(32, 32, 2, 0.0), test = ref;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) test.rgb[3 * (std::size_t(y) * 32 + x) + c] = (x + y) % 2 ? 0.1f : -0.1f;
  EXPECT_LT(blurred_rmse(test, ref, 1.0), 0.01 * 0.1);
}
