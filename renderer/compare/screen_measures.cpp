#include "renderer/compare/screen_measures.h"

#include <stdexcept>

namespace pdrt {

ScreenReference screen_reference(const Image& reference, const std::array<Image, 2>& halves,
                                 const std::array<int, 2>& half_spp) {
  ScreenReference r;
  r.image = &reference;
  for (std::size_t s = 0; s < kBlurSigmas.size(); ++s) {
    r.blurred[s] = gaussian_blur(reference, kBlurSigmas[s]);
    // Blurring is linear: the blurred halves' difference measures the blurred reference's noise.
    r.blurred_noise[s] = reference_noise(gaussian_blur(halves[0], kBlurSigmas[s]), half_spp[0],
                                         gaussian_blur(halves[1], kBlurSigmas[s]), half_spp[1]);
  }
  r.noise_power = reference_noise_power(halves[0], half_spp[0], halves[1], half_spp[1]);
  r.ldr = flip_view(reference.rgb, reference.width, reference.height);
  r.hdr = hdr_flip_reference(reference);
  return r;
}

ScreenMeasures screen_measures(const ScreenReference& ref, const std::vector<Image>& seeds) {
  if (seeds.empty() || !ref.image) throw std::invalid_argument("screen_measures: no images");
  const Image& reference = *ref.image;
  const int W = reference.width, H = reference.height;
  ScreenMeasures m;
  for (std::size_t s = 0; s < kBlurSigmas.size(); ++s) {
    std::vector<Image> blurred;
    for (const Image& im : seeds) blurred.push_back(gaussian_blur(im, kBlurSigmas[s]));
    m.blurred[s] = seed_statistics(blurred, ref.blurred[s], ref.blurred_noise[s]);
  }
  m.spectrum.assign(std::size_t(W) * H, 0.0);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const std::vector<double> p = power_spectrum(luminance_error(seeds[k], reference), W, H);
    for (std::size_t i = 0; i < p.size(); ++i) m.spectrum[i] += p[i] / double(seeds.size());
    m.low_share.push_back(low_frequency_share(split_power(p, W, H), ref.noise_power));
    std::vector<float> ldr = flip_error(ref.ldr, flip_view(seeds[k].rgb, W, H));
    std::vector<float> hdr = hdr_flip(ref.hdr, seeds[k]);
    m.flip_ldr.push_back(mean_flip(ldr));
    m.flip_hdr.push_back(mean_flip(hdr));
    if (k == 0) m.flip_ldr_map = std::move(ldr), m.flip_hdr_map = std::move(hdr);
  }
  m.low_share_mean = seed_mean(m.low_share);
  m.flip_ldr_mean = seed_mean(m.flip_ldr);
  m.flip_hdr_mean = seed_mean(m.flip_hdr);
  return m;
}

}  // namespace pdrt
