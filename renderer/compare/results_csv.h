#pragma once
// results.csv: one row per (sampler, spp, seed), with the (sampler, spp) statistics repeated,
// so a figure can be regenerated from the CSV alone.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

namespace pdrt {

void write_results_csv(const ReportContext& ctx, const CompareResults& results);

}  // namespace pdrt
