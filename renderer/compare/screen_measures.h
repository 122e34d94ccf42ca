#pragma once
// The measures of a comparison that see where on screen the error sits (issue 31), per
// (sampler, spp) over its seeds: the RMSE of the error blurred by 1 and 2 pixels
// (blurred_error.h) with the RMSE's seed statistics and reference correction, the share of the
// luminance error's power below 1/4 cycle per pixel (error_spectrum.h), LDR- and HDR-FLIP
// (flip.h) with their means over seeds and 95 % intervals, the error's 2-D power spectrum
// averaged over the seeds, and seed 0's FLIP maps.
#include "renderer/compare/blurred_error.h"
#include "renderer/compare/error_spectrum.h"
#include "renderer/compare/flip.h"
#include "renderer/compare/seed_statistics.h"

#include <array>
#include <vector>

namespace pdrt {

// What every run's measures compare with, prepared once from the reference and its halves.
struct ScreenReference {
  const Image* image = nullptr;                                  // the reference
  std::array<Image, kBlurSigmas.size()> blurred;                 // it blurred by each sigma
  std::array<ReferenceNoise, kBlurSigmas.size()> blurred_noise;  // the noise of its blurred halves
  PowerSplit noise_power;  // its noise's luminance power, below the cutoff and in all
  FlipView ldr;            // LDR-FLIP's view of it
  HdrFlipReference hdr;    // HDR-FLIP's views of it at each exposure
};
// `reference` must outlive the result; halves of half_spp samples per pixel.
ScreenReference screen_reference(const Image& reference, const std::array<Image, 2>& halves,
                                 const std::array<int, 2>& half_spp);

struct ScreenMeasures {
  // Per sigma of kBlurSigmas: seed_statistics of the blurred images against the blurred
  // reference, so rmse_mean, rmse_ci95 and the per-seed rmse are those of the blurred error.
  std::array<SeedStatistics, kBlurSigmas.size()> blurred;
  std::vector<double> low_share, flip_ldr, flip_hdr;  // per seed (mean FLIP over the image)
  SeedMean low_share_mean, flip_ldr_mean, flip_hdr_mean;
  std::vector<double> spectrum;                   // power_spectrum of the luminance error, mean over seeds
  std::vector<float> flip_ldr_map, flip_hdr_map;  // seed 0's per-pixel FLIP
};
ScreenMeasures screen_measures(const ScreenReference& reference, const std::vector<Image>& seeds);

}  // namespace pdrt
