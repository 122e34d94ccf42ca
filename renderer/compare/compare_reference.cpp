#include "renderer/compare/compare_reference.h"

#include "renderer/compare/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pdrt {

double CompareReference::corrected_rmse(const Image& im) const {
  const double e = rmse(im, image);
  return std::sqrt(std::max(0.0, e * e - noise.variance));
}

CompareReference render_reference(const ReportContext& ctx) {
  CompareReference ref;
  ref.setup = reference_setup(ctx.base, ctx.o);
  const auto& half_spp = ref.setup.half_spp;
  std::array<Image, 2>& halves = ref.halves;
  for (int h = 0; h < 2; ++h) {
    CompareJob jb;
    jb.kind = CompareJob::Kind::Reference, jb.half = h;
    CompareRender r = ctx.get(jb);
    halves[h] = std::move(r.image);
    ref.file[h] = r.file;
    ref.cached = ref.cached && r.cached;
    if (!r.cached) ref.seconds += r.seconds;
  }
  ref.image = halves[0];
  for (std::size_t i = 0; i < ref.image.rgb.size(); ++i)
    ref.image.rgb[i] = float((double(halves[0].rgb[i]) * half_spp[0] + double(halves[1].rgb[i]) * half_spp[1]) /
                             double(ctx.o.reference_spp));
  ref.noise = reference_noise(halves[0], half_spp[0], halves[1], half_spp[1]);
  char buf[160];
  std::snprintf(buf, sizeof buf, "reference variance %.4g per pixel channel (RMSE %.5f), subtracted from every MSE",
                ref.noise.variance, std::sqrt(ref.noise.variance));
  ctx.say(buf);
  ctx.write_png("images/reference.png", display_rgb(ref.image));
  return ref;
}

}  // namespace pdrt
