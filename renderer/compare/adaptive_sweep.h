#pragma once
// The adaptive part of a comparison (--adaptive): per sampler a sweep of the threshold
// (centre x 2^k, k = -4..4, and on up to 8 while even the cheapest step reaches the target),
// each step compared with uniform sampling at equal samples, and the samples needed to reach
// the uniform RMSE at the target spp. Step 0 (the default threshold) also gets its image and
// sample-count map.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

namespace pdrt {

// Fills results.adaptive, writes step 0's images and says a line per step and per sampler.
// Needs results.reference and results.runs.
void run_adaptive_sweep(const ReportContext& ctx, CompareResults& results);

// Writes adaptive.csv: one row per sweep step.
void write_adaptive_csv(const ReportContext& ctx, const CompareResults& results);

}  // namespace pdrt
