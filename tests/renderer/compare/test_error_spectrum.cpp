// The error spectrum and its low-frequency share (renderer/compare/error_spectrum.h).
#include "renderer/compare/error_spectrum.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace pdrt;

namespace {

// An image whose every channel at (x, y) is f(x, y).
Image field(int w, int h, const std::function<double(int, int)>& f) {
  Image im;
  im.width = w, im.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) im.rgb.push_back(float(f(x, y)));
  return im;
}

Image zero(int w, int h) {
  return field(w, h, [](int, int) { return 0.0; });
}

}  // namespace

// Parseval: the periodogram |F|^2 / (W H) sums to the sum of squares.
TEST(ErrorSpectrum, PowerSumsToTheSquaredError) {
  Rng rng(7);
  std::vector<double> e(24 * 20);
  double s = 0;
  for (double& v : e) v = rng.uniform() - 0.5, s += v * v;
  double p = 0;
  for (double v : power_spectrum(e, 24, 20)) p += v;
  EXPECT_NEAR(p, s, 1e-9 * s);
}

// White error spreads its power evenly, so the share below 1/4 cycle per pixel is the disc's
// area pi / 16 = 0.196 (on the 64x64 grid 793 of 4096 frequencies, 0.1936). One 64x64 image's
// share has a standard deviation of about 0.009; the mean of four, 0.0045; tolerance 0.02.
TEST(ErrorSpectrum, WhiteNoiseLowFrequencyShareIsPiOverSixteen) {
  double share = 0;
  for (int k = 0; k < 4; ++k) {
    Rng rng(11 + k);
    const Image noise = field(64, 64, [&](int, int) { return rng.uniform() - 0.5; });
    share += low_frequency_share(noise, zero(64, 64)) / 4;
  }
  EXPECT_NEAR(share, M_PI / 16, 0.02);
}

// A smooth ramp across the image: its mean and its slow variation are below 1/4 cycle per pixel;
// only the jump where the periodic extension wraps puts about 1 % of the power above.
TEST(ErrorSpectrum, SmoothRampErrorIsNearlyAllLowFrequency) {
  const Image ramp = field(64, 64, [](int x, int y) { return 0.01 * (x + 0.5 * y); });
  EXPECT_GT(low_frequency_share(ramp, zero(64, 64)), 0.95);
}

// The mean error (DC, i.e. bias) counts as low-frequency error.
TEST(ErrorSpectrum, ConstantErrorIsAllLowFrequency) {
  EXPECT_NEAR(low_frequency_share(field(32, 32, [](int, int) { return 0.3; }), zero(32, 32)), 1.0, 1e-12);
}

// A one-pixel checkerboard has all its power at (0.5, 0.5) cycles per pixel.
TEST(ErrorSpectrum, CheckerboardErrorHasNoLowFrequencyPower) {
  const Image check = field(32, 32, [](int x, int y) { return (x + y) % 2 ? 0.2 : -0.2; });
  EXPECT_NEAR(low_frequency_share(check, zero(32, 32)), 0.0, 1e-9);
}

// The reference's noise power is taken out of both parts of the share.
TEST(ErrorSpectrum, ReferenceNoisePowerIsTakenOut) {
  PowerSplit error{3.0, 10.0}, noise{1.0, 6.0};
  EXPECT_DOUBLE_EQ(low_frequency_share(error, noise), 0.5);
  EXPECT_TRUE(std::isnan(low_frequency_share(noise, noise)));
}
