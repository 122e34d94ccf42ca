#pragma once
// The statistics `pdrt analyze` reports for one or more realizations of a point process,
// gathered into the stats.json document (schema in docs of analyze_point_sets below).
#include "sampling/analysis/chi_square.h"
#include "sampling/analysis/max_empty_ball.h"
#include "sampling/analysis/periodogram.h"
#include "sampling/core/point_set.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace pdrt {

struct AnalysisOptions {
  bool periodic = false;  // toroidal distances for min distance, coverage and prefixes
  int resolution = 0;     // periodogram grid; 0 = default_periodogram_resolution
};

// Throws InputError unless every set has the dim of the first (the message names the file).
void check_same_dim(std::span<const PointSet> sets, std::span<const std::string> names);

// The periodogram resolution to use (nullopt: the default for these sets); throws UsageError
// naming --resolution when the requested one is odd or outside the limits for these sets.
int resolve_resolution(std::span<const PointSet> sets, std::optional<int> requested);

struct FileStats {
  std::string file;
  std::size_t count = 0;
  int dim = 0;
  double min_distance = 0.0;
  double relative_radius = 0.0;
  double disk_radius = 0.0;  // smallest CSV radius if present, else min_distance
  bool disk_radius_from_csv = false;
  EmptyBall empty;
  bool maximal = false;  // empty.radius <= disk_radius (up to CSV rounding)
  ChiSquare chi2;
};

FileStats analyze_point_set(const PointSet& points, const std::string& name, bool periodic);

struct Analysis {
  nlohmann::json stats;
  Periodogram periodogram;
};

// Everything for stats.json. Top-level scalars (count, min_distance, relative_radius,
// max_empty_radius, chi2_p, ...) describe the first file, which is also the one whose
// prefix_relative_radius is given (entry n-2 for the first n points, n = 2..N); `per_file`
// repeats them for every file; `spectrum` holds the periodogram averaged over all files
// (the realizations) and its radial statistics.
Analysis analyze_point_sets(std::span<const PointSet> sets, std::span<const std::string> names,
                            const AnalysisOptions& options);

// Rounds to 9 significant digits (as in the point CSV) so stats.json stays readable;
// non-finite values pass through (nlohmann writes them as null).
double round_sig9(double x);

}  // namespace pdrt
