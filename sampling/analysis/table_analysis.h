#pragma once
// `pdrt analyze --table`: a sample table seen as point sets (one realization per table) and
// its hierarchical quality: rho of every prefix and, for the pixel family, of every pixel's
// own subsequence.
#include "sampling/core/point_set.h"
#include "sampling/samplers/sample_table.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace pdrt {

// Table k as a torus point set in rank order; the pixel family's tile is mapped to [0,1)^2.
std::vector<PointSet> table_point_sets(const SampleTable& table);

// {family, tables, points, tile, prefix_rho_min (prefixes >= 16 points, over all tables),
//  full_rho_min, full_rho_mean, and for the pixel family pixel_prefix_rho_min (each pixel's
//  subsequence, in pixel units, prefixes >= 16), per_pixel_min}
nlohmann::json table_quality(const SampleTable& table, const std::vector<PointSet>& sets);

}  // namespace pdrt
