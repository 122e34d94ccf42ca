// The screen-space measures of a run over its seeds (renderer/compare/screen_measures.h).
#include "renderer/compare/image_metrics.h"
#include "renderer/compare/screen_measures.h"
#include "sampling/core/rng.h"
#include "tests/support/image_fixtures.h"

#include <gtest/gtest.h>

using namespace pdrt;

namespace {
Image noisy(const Image& base, uint64_t seed, double amplitude) {
  Image im = base;
  Rng rng(seed);
  for (float& v : im.rgb) v += float(amplitude * (rng.uniform() - 0.5));
  return im;
}
}  // namespace

// With a noiseless reference (identical halves) every seed's numbers are the direct measures:
// the blurred RMSE, the low-frequency share and the mean FLIP of that seed alone.
TEST(ScreenMeasures, PerSeedValuesAreTheDirectMeasures) {
  const Image ref = test::flat_image(16, 12, 0.4f, 0.4f, 0.4f);
  const ScreenReference sr = screen_reference(ref, {ref, ref}, {8, 8});
  const std::vector<Image> seeds = {noisy(ref, 1, 0.2), noisy(ref, 2, 0.2), noisy(ref, 3, 0.2)};
  const ScreenMeasures m = screen_measures(sr, seeds);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    for (std::size_t s = 0; s < kBlurSigmas.size(); ++s)
      EXPECT_NEAR(m.blurred[s].rmse[k], blurred_rmse(seeds[k], ref, kBlurSigmas[s]), 1e-6);
    EXPECT_NEAR(m.low_share[k], low_frequency_share(seeds[k], ref), 1e-9);
    EXPECT_NEAR(m.flip_ldr[k], mean_flip(ldr_flip(ref, seeds[k])), 1e-6);
    EXPECT_NEAR(m.flip_hdr[k], mean_flip(hdr_flip(ref, seeds[k])), 1e-6);
  }
  EXPECT_EQ(m.flip_ldr_map, ldr_flip(ref, seeds[0]));
  EXPECT_NEAR(m.flip_hdr_mean.mean, (m.flip_hdr[0] + m.flip_hdr[1] + m.flip_hdr[2]) / 3, 1e-12);
}
