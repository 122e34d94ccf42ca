#pragma once
// The blurred-error heat maps (issue 31 item 5): every run's seed-0 luminance error blurred by a
// Gaussian of kBlurredMapSigma pixels, |Y(blur(image) - blur(reference))|, which is the error the
// blurred RMSE measures, on the heat ramp with one scale per spp shared by the samplers (the
// 99th percentile, as the error maps of heat_maps.h). White error fades under the blur; error
// pushed to high frequencies (screen-space blue noise) fades more.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

namespace pdrt {

inline constexpr double kBlurredMapSigma = 1.0;

// Fills every run's blurred_error and writes its blurred_error_file
// (errors/<sampler>-<spp>-blurred.png); fills results.blurred_heat_scale. Needs
// results.reference and results.runs.
void write_blurred_heat_maps(const ReportContext& ctx, CompareResults& results);

}  // namespace pdrt
