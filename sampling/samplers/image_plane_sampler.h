#pragma once
// `poisson-ip`: the image plane sampled by one hierarchical Poisson-disk pattern across pixels
// (issue 31 item 2; McCool & Fiume §3, image_plane_pattern.h), the other families from
// `poisson`. For a render of spp samples per pixel the pattern's prefix of spp * P^2 points
// covers a period of P x P pixels (image_plane_period), tiled over the image, shifted per seed
// by one uniform toroidal shift of the whole pattern: every point is uniform over the period,
// so the density of samples at every film point is exactly spp per pixel area. Pixel (x, y)
// takes the points that fall in it, in generation order: sample j of the pixel family
// (bounce 0, the film point) is the j-th of them as an offset within the pixel; its lens,
// time, light and gloss samples and every deeper pixel-family stream are the base sampler's
// at index j. A pixel's count varies (its expectation is spp): samples_in_pixel gives it, and
// the renderer splats the samples and divides by the expected filter weight (docs/sampling.md).
#include "sampling/samplers/sampler.h"

#include <cstdint>
#include <memory>
#include <string>

namespace pdrt {

// `base` gives every stream but the film point's; the period is chosen for
// shape.samples_per_pixel. Throws UsageError when that exceeds the pattern's points.
std::unique_ptr<Sampler> make_image_plane_sampler(std::unique_ptr<Sampler> base, const SamplerShape& shape,
                                                  std::string name);

}  // namespace pdrt
