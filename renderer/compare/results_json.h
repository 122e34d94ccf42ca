#pragma once
// results.json, the report's record (docs/compare.md): the settings, the reference, every
// run with its per-seed values, the heat maps' scales and crops, the convergence view and
// the adaptive sweep, each with a line saying how it is computed.
#include "renderer/compare/compare_results.h"
#include "renderer/compare/report_context.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace pdrt {

nlohmann::json results_json(const ReportContext& ctx, const CompareResults& results);

// Writes results.json; returns its path.
std::filesystem::path write_results_json(const ReportContext& ctx, const CompareResults& results);

}  // namespace pdrt
