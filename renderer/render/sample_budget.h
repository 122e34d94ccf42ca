#pragma once
// What a render will cost, said before it starts: the total camera samples (width x height
// x spp, or x max_spp when adaptive, the most it may take). Above kMaxTotalSamples pdrt
// refuses unless the user passes --allow-long-render: 10^10 samples is about 46 min at the
// 277 ns per sample bench_render measures on a simple scene on the 2-core reference host
// (docs/renderer.md), and hours for a scene with glass or many lights; a typo such as
// --spp 2000000000 would otherwise run for days without a word.
#include "renderer/scene/scene_desc.h"

#include <string>

namespace pdrt {

inline constexpr double kMaxTotalSamples = 1e10;
inline constexpr double kSecondsPerSample = 277e-9;  // bench_render, simple scene: a rough lower bound
inline constexpr const char* kAllowLongRenderHelp =
    "Render even when the total samples exceed the 1e10 limit (docs/renderer.md, Limits)";

// The most camera samples rendering `scene` may take.
double scene_sample_count(const SceneDesc& scene);
// "24x16 pixels x 64 spp" (or "x max_spp 256, adaptive").
std::string describe_sample_count(const SceneDesc& scene);

// "1.54e+03 samples (about 0 s at 277 ns per sample)": what to expect, said before starting.
std::string format_sample_cost(double total);

// UsageError when `total` exceeds kMaxTotalSamples and `allow` is false; `what` says where
// the number comes from.
void check_sample_budget(double total, const std::string& what, bool allow);

}  // namespace pdrt
