#include "renderer/render/render_region.h"

#include "renderer/render/adaptive_metric.h"
#include "sampling/core/errors.h"
#include "sampling/core/warnings.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pdrt {

RenderRegion render_region(const SceneDesc& desc) {
  const AdaptiveDesc& ad = desc.sampler.adaptive;
  const int W = desc.film.width, H = desc.film.height;
  RenderRegion r;
  r.crop = crop_pixels(desc.film.crop_window, W, H);
  const int reach =
      desc.film.filter.reconstruction == Reconstruction::Splat ? int(std::ceil(desc.film.filter.radius)) + 1 : 0;
  int margin = reach;
  if (ad.enabled) {
    for (int64_t p = ad.min_spp; p < ad.max_spp; p *= 2) ++r.margin_rounds;
    margin = reach + ++r.margin_rounds * (1 + reach);
  }
  r.metric_needs_mean = ad.enabled && AdaptiveMetric(ad).needs_image_mean();
  r.rect = PixelRect{std::max(0, r.crop.x0 - margin), std::min(W, r.crop.x1 + margin), std::max(0, r.crop.y0 - margin),
                     std::min(H, r.crop.y1 + margin)};
  return r;
}

void warn_adaptive_crop(const SceneDesc& desc, const RenderRegion& region, int rounds, bool quiet) {
  const bool cropped = region.crop.width() < desc.film.width || region.crop.height() < desc.film.height;
  if (desc.sampler.adaptive.enabled && cropped && !quiet && (rounds > region.margin_rounds || region.metric_needs_mean))
    warn(std::string("pdrt: warning: the crop window of an adaptive render may differ from the full render's crop (") +
         (region.metric_needs_mean
              ? adaptive_metric_name(AdaptiveMetricKind::ErrorPerSample) + std::string(" compares with the crop's mean")
              : "refinement ran past the rounds the crop's margin covers") +
         ")");
}

}  // namespace pdrt
