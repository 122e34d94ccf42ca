#pragma once
// The samplers' names (make_sampler in sampler.h builds them), apart from sampler.h so that the
// scene description can name its default without the sampler interface.
#include "sampling/core/name_table.h"

#include <iterator>
#include <string>
#include <vector>

namespace pdrt {

// The samplers `make_sampler` builds, and their names: the one list of them (the scene file's
// sampler.type, --sampler, --samplers, help texts and messages all read it). Every kind but
// `regular` is a Monte Carlo sampler, unbiased over seeds; `regular` is Cook's regular sampling
// (the same deterministic pattern in every pixel; biased, for aliasing demos).
enum class SamplerKind {
  Random,
  Jitter,
  Poisson,
  Poisson065,
  Sobol,
  Pmj02bn,
  ZSobol,
  PoissonSS,
  PoissonBN,
  PoissonIP,
  Regular
};
inline constexpr NamedValue<SamplerKind> kSamplerNames[] = {
    {SamplerKind::Random, "random"},        {SamplerKind::Jitter, "jitter"},
    {SamplerKind::Poisson, "poisson"},      {SamplerKind::Poisson065, "poisson-065"},
    {SamplerKind::Sobol, "sobol"},          {SamplerKind::Pmj02bn, "pmj02bn"},
    {SamplerKind::ZSobol, "zsobol"},        {SamplerKind::PoissonSS, "poisson-ss"},
    {SamplerKind::PoissonBN, "poisson-bn"}, {SamplerKind::PoissonIP, "poisson-ip"},
    {SamplerKind::Regular, "regular"}};
// What `compare` sweeps unless told: the project's own and the classic baselines (the peers
// pmj02bn and zsobol on request, so the default sweep's time stays as documented).
inline constexpr SamplerKind kCompareDefaultSamplers[] = {
    SamplerKind::Random, SamplerKind::Jitter, SamplerKind::Poisson, SamplerKind::Poisson065, SamplerKind::Sobol};
static_assert(covers_in_order(kSamplerNames) && std::size(kSamplerNames) == std::size_t(SamplerKind::Regular) + 1,
              "kSamplerNames names every SamplerKind, in order, regular last");
inline const char* sampler_name(SamplerKind k) { return name_in(kSamplerNames, k); }
// kCompareDefaultSamplers by name (inline: the plan readers link without the samplers).
inline std::vector<std::string> compare_default_sampler_names() {
  std::vector<std::string> n;
  for (SamplerKind k : kCompareDefaultSamplers) n.push_back(sampler_name(k));
  return n;
}
// The samplers that lay each dimension's samples out over the image in Morton order (zsobol,
// poisson-ss), and the bits of Morton and sample index they need for a w x h image whose first
// pass takes spp samples per pixel: 2 ceil(log2 max(w, h)) + ceil(log2 spp), at most
// kPixelOrderBits (their 32-bit fixed-point values see no more).
inline bool orders_pixels(SamplerKind k) { return k == SamplerKind::ZSobol || k == SamplerKind::PoissonSS; }
inline constexpr int kPixelOrderBits = 32;
inline int pixel_order_bits(long long spp, int w, int h) {
  auto ceil_log2 = [](long long n) {
    int b = 0;
    while (b < 62 && (1LL << b) < n) ++b;
    return b;
  };
  return 2 * ceil_log2(w > h ? w : h) + ceil_log2(spp);
}
// `poisson-ip`: the pixel family from one image-plane Poisson-disk pattern across pixels
// (image_plane_sampler.h); it renders only by splatting, without adaptive refinement.
inline bool samples_image_plane(SamplerKind k) { return k == SamplerKind::PoissonIP; }
// False for a name that is none of kSamplerNames.
inline bool parse_sampler(const std::string& name, SamplerKind* out) { return parse_name_in(kSamplerNames, name, out); }

}  // namespace pdrt
