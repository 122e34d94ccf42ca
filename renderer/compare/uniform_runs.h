#pragma once
// The uniform runs of a comparison: every sampler at every --spp over every seed, each seed's
// error against the reference, the statistics over the seeds (seed_statistics.h), the error
// spectrum, and the samples the sampler gave seed 0's pixels (stream_analysis.h).
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

namespace pdrt {

// Fills results.runs (by sampler, then spp) and results.threads; writes each run's seed-0
// image and says its line. Needs results.reference.
void render_uniform_runs(const ReportContext& ctx, CompareResults& results);

}  // namespace pdrt
