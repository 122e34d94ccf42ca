#pragma once
// Heat maps of the report: a perceptually ordered dark-to-bright colour ramp, and the error
// maps of the uniform runs, which share one scale per sample count (the 99th percentile over
// the samplers) so that they compare across samplers.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"
#include "renderer/scene/vec3.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pdrt {

// The ramp in display RGB at t = 0, 1/4, ..., 1 (results.json carries it so the report's
// colour bars match the PNGs).
inline constexpr float kHeatStops[5][3] = {
    {0, 0, 0.02f}, {0.33f, 0.06f, 0.43f}, {0.73f, 0.21f, 0.33f}, {0.98f, 0.55f, 0.04f}, {0.99f, 1.0f, 0.64f}};

// The ramp's colour at t (clamped to [0, 1]).
Vec3 heat(float t);

// The ramp's colours of `values` (each scaled by 1 / scale) as display RGB.
std::vector<float> heat_rgb(const std::vector<float>& values, float scale);

// The scale of heat maps that share one: the 99th percentile of `values` (brighter ones clip),
// at least 1e-6 so that an all-zero map stays the ramp's zero colour.
float heat_scale(std::vector<float> values);

// Writes maps[i] as runs[i]'s PNG file_of(runs[i]) on the heat ramp, with one scale per spp
// (heat_scale over that spp's maps, so the samplers compare); returns the scales by spp.
std::map<int, float> write_heat_pngs(const ReportContext& ctx, const std::vector<UniformRun>& runs,
                                     const std::vector<std::vector<float>>& maps,
                                     const std::function<std::string(const UniformRun&)>& file_of);

// Writes every run's error map (run.error_file) and fills results.heat_scale. Needs
// results.reference and results.runs.
void write_heat_maps(const ReportContext& ctx, CompareResults& results);

}  // namespace pdrt
