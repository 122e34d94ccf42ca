#pragma once
// Side-by-side crops of the reference's most detailed square (the largest sum of luminance
// gradient norms), one sheet per sample count: every sampler's seed-0 image, then the reference.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

#include <array>

namespace pdrt {

// The square {x, y, side} where `ref` has the most detail; side max(8, min(W, H) / 4), at most min(W, H).
std::array<int, 3> detail_window(const Image& ref);

// Writes images/crops-<spp>.png and fills results.crops. Needs results.reference and results.runs.
void write_detail_crops(const ReportContext& ctx, CompareResults& results);

}  // namespace pdrt
