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
  std::vector<std::vector<float>> maps;
  for (const UniformRun& r : results.runs) maps.push_back(r.blurred_error);
  results.blurred_heat_scale =
      write_heat_pngs(ctx, results.runs, maps, [](const UniformRun& r) { return r.blurred_error_file; });
}

}  // namespace pdrt
