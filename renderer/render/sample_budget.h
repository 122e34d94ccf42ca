#pragma once
// What a render will cost, said before it starts: the total camera samples (width x height
// x spp, or x max_spp when adaptive, the most it may take) and the time they take. `render`
// times them on this machine and this scene (render_estimate.h); `compare`, which builds no
// scene before it starts, takes kSecondsPerSample. Above kMaxEstimatedSeconds pdrt refuses
// unless the user passes --allow-long-render (or bounds the render with --time-limit): a typo
// such as --spp 2000000000 would otherwise run for days without a word.
#include "renderer/scene/scene_desc.h"

#include <string>

namespace pdrt {

// bench_render on a simple scene on the 2-core reference host (docs/renderer.md): a lower bound.
inline constexpr double kSecondsPerSample = 277e-9;
// 10^10 samples at that rate, the limit before renders were timed: 46 min.
inline constexpr double kMaxEstimatedSeconds = 1e10 * kSecondsPerSample;
inline constexpr const char* kAllowLongRenderHelp =
    "Render even when the estimated time exceeds the limit of 46 min (docs/renderer.md, Limits)";

// The most camera samples rendering `scene` may take.
double scene_sample_count(const SceneDesc& scene);
// "24x16 pixels x 64 spp" (or "x max_spp 256, adaptive").
std::string describe_sample_count(const SceneDesc& scene);

// "1.54e+03 samples (about 0.4 ms at 277 ns per sample)": what to expect, said before
// starting; `measured` adds "measured on this scene"; `fixed_seconds`: a cost that no sample
// carries (the passes' loops, render_estimate.h).
std::string format_sample_cost(double total, double seconds_per_sample, bool measured, double fixed_seconds = 0);

// UsageError when `total` samples at `seconds_per_sample` exceed kMaxEstimatedSeconds and
// `allow` is false; `what` says where the number comes from.
void check_sample_budget(double total, double seconds_per_sample, bool measured, const std::string& what, bool allow);

}  // namespace pdrt
