#include "renderer/compare/blurred_heat_maps.h"

#include "renderer/compare/blurred_error.h"
#include "renderer/compare/heat_maps.h"

namespace pdrt {

void write_blurred_heat_maps(const ReportContext& ctx, CompareResults& results) {
  const Image blurred_reference = gaussian_blur(results.reference.image, kBlurredMapSigma);
  for (UniformRun& r : results.runs) {
    r.blurred_error = blurred_error_map(r.image, blurred_reference, kBlurredMapSigma);
    r.blurred_error_file = "errors/" + r.sampler + "-" + std::to_string(r.spp) + "-blurred.png";
  }
  for (int n : ctx.o.spp) {
    std::vector<float> all;
    for (const UniformRun& r : results.runs)
      if (r.spp == n) all.insert(all.end(), r.blurred_error.begin(), r.blurred_error.end());
    const float scale = heat_scale(std::move(all));
    results.blurred_heat_scale[n] = scale;
    for (const UniformRun& r : results.runs)
      if (r.spp == n) ctx.write_png(r.blurred_error_file, heat_rgb(r.blurred_error, scale));
  }
}

}  // namespace pdrt
