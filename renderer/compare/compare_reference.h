#pragma once
// The reference of a comparison (compare_job.h): its two halves, rendered or read from the
// cache, their samples-weighted mean, and their difference as the measure of its noise, which
// every MSE of the report has subtracted.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

namespace pdrt {

// Gets both halves, says the reference's variance and writes images/reference.png.
CompareReference render_reference(const ReportContext& ctx);

}  // namespace pdrt
