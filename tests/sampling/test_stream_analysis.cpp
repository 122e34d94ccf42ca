// The analysis of the samples a render used (compare's used_samples): rho of each pixel's
// prefix and the periodogram averaged over pixels, checked on samplers whose answer is known.
#include "sampling/analysis/stream_analysis.h"
#include "sampling/samplers/poisson_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pdrt {
namespace {

double mean_power(const StreamAnalysis& a, std::size_t from, std::size_t to) {
  double s = 0;
  for (std::size_t b = from; b < to; ++b) s += a.spectrum.power[b];
  return s / double(to - from);
}

// White noise: power 1 at every frequency. 1024 pixels x 64 points; each fine annulus holds
// >= 6 periodogram values of 1024 sets, so its mean has a standard error below 0.02 at
// power 1; 0.1 is five of them.
TEST(StreamAnalysis, RandomSamplesAreWhiteNoise) {
  auto s = make_sampler("random", 3);
  const StreamAnalysis a = analyze_stream(*s, Family::Lens, 64, 64, 64, 1024);
  EXPECT_EQ(a.pixels, 1024);
  EXPECT_EQ(a.spp, 64);
  ASSERT_FALSE(a.spectrum.power.empty());
  for (std::size_t b = 0; b < a.spectrum.power.size(); ++b) EXPECT_NEAR(a.spectrum.power[b], 1.0, 0.1) << b;
  EXPECT_LT(a.rho_mean, 0.3);  // white noise packs badly
}

// Stratified samples have little power at low frequency: 16 jittered points per pixel remove
// most of it below the 4-cycle stratum frequency (white noise: 1).
TEST(StreamAnalysis, JitteredSamplesHaveLittleLowFrequencyPower) {
  auto s = make_sampler("jitter", 3);
  const StreamAnalysis a = analyze_stream(*s, Family::Light, 32, 32, 16, 1024);
  EXPECT_LT(mean_power(a, 0, 2), 0.5);
  EXPECT_NEAR(mean_power(a, a.spectrum.power.size() - 4, a.spectrum.power.size()), 1.0, 0.15);
}

// The poisson-065 tables' bar (every prefix of >= 16 points has rho >= 0.65 on the torus) holds
// for the samples a render uses: a table's toroidal shift and symmetry keep distances.
TEST(StreamAnalysis, Poisson065SamplesKeepTheTablesRhoBarInEveryPixel) {
  auto s = make_poisson_sampler(3, default_tables(TableSetKind::Poisson065));
  for (Family f : {Family::Lens, Family::Light, Family::Gloss}) {
    const StreamAnalysis a = analyze_stream(*s, f, 40, 30, 64, 1200);
    EXPECT_EQ(a.pixels, 1200);
    EXPECT_GE(a.rho_min, 0.65) << family_name(f);
    EXPECT_GE(a.rho_mean, a.rho_p05);
    EXPECT_GE(a.rho_p05, a.rho_min);
  }
}

TEST(StreamAnalysis, OnePointHasNoRhoAndPixelsAreCappedByTheImage) {
  auto s = make_sampler("sobol", 3);
  const StreamAnalysis a = analyze_stream(*s, Family::Time, 5, 4, 1, 1024);
  EXPECT_EQ(a.pixels, 20);
  EXPECT_TRUE(std::isnan(a.rho_mean));
  EXPECT_TRUE(a.periodic);  // the time family is measured on the torus
  EXPECT_FALSE(analyze_stream(*s, Family::Pixel, 5, 4, 4, 1024).periodic);
}

}  // namespace
}  // namespace pdrt
