#include "sampling/analysis/table_analysis.h"

#include "sampling/analysis/discrepancy.h"
#include "sampling/measures/min_distance.h"

#include <algorithm>
#include <limits>

namespace pdrt {

std::vector<PointSet> table_point_sets(const SampleTable& t) {
  std::vector<PointSet> sets(t.table_count());
  const double P = t.params.tile;
  for (uint32_t k = 0; k < t.table_count(); ++k) {
    PointSet& ps = sets[k];
    ps.dim = t.dim;
    ps.periodic = true;
    const std::size_t n = t.radius[k].size();
    ps.coords.resize(n * t.dim);
    ps.radius.resize(n);
    if (t.params.family != Family::Pixel) {
      for (std::size_t i = 0; i < n * t.dim; ++i) ps.coords[i] = t.coords[k][i] * 0x1.0p-32;
      ps.radius.assign(t.radius[k].begin(), t.radius[k].end());
      continue;
    }
    // Pixel tables are stored per pixel and the tile's global rank order is not kept, so the
    // set comes out in pixel order (spectra and min distance do not depend on order).
    const uint32_t tile = t.params.tile;
    for (uint32_t cell = 0; cell < tile * tile; ++cell)
      for (uint32_t j = 0; j < t.cell_count[k][cell]; ++j) {
        std::size_t i = t.cell_start[k][cell] + j;
        ps.coords[2 * i] = (cell % tile + t.coords[k][2 * i] * 0x1.0p-32) / P;
        ps.coords[2 * i + 1] = (cell / tile + t.coords[k][2 * i + 1] * 0x1.0p-32) / P;
        ps.radius[i] = t.radius[k][i] / P;
      }
  }
  return sets;
}

nlohmann::json table_quality(const SampleTable& t, const std::vector<PointSet>& sets) {
  nlohmann::json j;
  j["family"] = family_name(t.params.family);
  j["tables"] = t.table_count();
  j["points"] = t.params.points;
  j["tile"] = t.params.tile;
  j["seed"] = t.params.seed;
  j["memory_bytes"] = t.memory_bytes();
  const bool pixel = t.params.family == Family::Pixel;
  double prefix_min = std::numeric_limits<double>::infinity(), full_min = prefix_min, full_sum = 0.0;
  double pixel_min = prefix_min;
  for (uint32_t k = 0; k < t.table_count(); ++k) {
    if (!pixel) {
      prefix_min = std::min(prefix_min, worst_prefix_rho(prefix_relative_radius(sets[k], true), 16));
    } else {
      // Each pixel's own subsequence, in pixel units, non-periodic (the pixel is not a torus).
      for (uint32_t cell = 0; cell < t.params.tile * t.params.tile; ++cell) {
        PointSet px;
        px.dim = 2;
        uint32_t start = t.cell_start[k][cell], n = t.cell_count[k][cell];
        px.coords.assign(t.coords[k].begin() + 2 * start, t.coords[k].begin() + 2 * (start + n));
        for (double& v : px.coords) v *= 0x1.0p-32;
        pixel_min = std::min(pixel_min, worst_prefix_rho(prefix_relative_radius(px, false), 16));
      }
    }
    double full = relative_radius(min_distance(sets[k], true), sets[k].size(), t.dim);
    full_min = std::min(full_min, full);
    full_sum += full / t.table_count();
  }
  if (t.dim == 1) {
    // Worst periodic discrepancy over the tables, of the 64-, 256- and 1024-point prefixes
    // and of the whole table.
    nlohmann::json d;
    std::vector<std::size_t> sizes = {64, 256, 1024};
    sizes.erase(std::remove_if(sizes.begin(), sizes.end(), [&](std::size_t n) { return n >= t.params.points; }),
                sizes.end());
    sizes.push_back(t.params.points);
    for (std::size_t n : sizes) {
      double worst = 0.0;
      for (const PointSet& ps : sets) {
        const std::size_t m = std::min(n, ps.size());
        worst = std::max(worst, periodic_discrepancy_1d({ps.coords.begin(), ps.coords.begin() + m}));
      }
      d[std::to_string(n)] = worst;
    }
    j["discrepancy_max"] = d;
  }
  if (!pixel) j["prefix_rho_min"] = prefix_min;
  j["full_rho_min"] = full_min;
  j["full_rho_mean"] = full_sum;
  if (pixel) {
    j["pixel_prefix_rho_min"] = pixel_min;
    j["per_pixel_min"] = t.per_pixel_min;
  }
  return j;
}

}  // namespace pdrt
