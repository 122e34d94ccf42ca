#pragma once
// The report's convergence view of the uniform runs: each sampler's slope of RMSE against spp
// on log-log axes (convergence.h), and the equal-time view: every sampler's RMSE interpolated
// at 8 common CPU times (over the range all samplers cover), with and without the CPU time the
// sampler itself takes (its profiled share).
#include "renderer/compare/compare_results.h"
#include "renderer/compare/compare.h"

namespace pdrt {

ConvergenceView convergence_view(const CompareOptions& o, const std::vector<UniformRun>& runs);

}  // namespace pdrt
