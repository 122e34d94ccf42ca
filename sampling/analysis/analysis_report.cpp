#include "sampling/analysis/analysis_report.h"

#include "sampling/core/errors.h"
#include "sampling/generators/generator.h"
#include "sampling/measures/min_distance.h"
#include "sampling/analysis/radial_spectrum.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace pdrt {

using nlohmann::json;

double round_sig9(double x) {
  if (x == 0.0) return 0.0;  // no "-0" in the JSON
  if (!std::isfinite(x)) return x;
  // The same digits as printf("%.9g") and strtod, ~3x faster (prefix arrays hold a value per point).
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 9).ptr;
  double v = x;
  std::from_chars(buf, end, v);
  return v;
}

namespace {

json rounded(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(round_sig9(x));
  return a;
}

json db_array(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(round_sig9(to_db(x)));
  return a;
}

json radial_json(const RadialSpectrum& rs, const Periodogram& pg) {
  const double unit = std::pow(pg.mean_count, 1.0 / pg.spectral_dim);
  std::vector<double> normalized;
  for (double f : rs.frequency) normalized.push_back(f / unit);
  json j = {
      {"frequency", rounded(rs.frequency)},
      {"frequency_normalized", rounded(normalized)},
      {"inner", rounded(rs.inner)},
      {"outer", rounded(rs.outer)},
      {"pixels", rs.pixels},
      {"power", rounded(rs.power)},
      {"power_db", db_array(rs.power)},
  };
  // Anisotropy measures variation over orientations, which a 1-D spectrum does not have.
  if (pg.spectral_dim == 2) {
    j["anisotropy"] = rounded(rs.anisotropy);
    j["anisotropy_db"] = db_array(rs.anisotropy);
  } else {
    j["anisotropy"] = nullptr;
    j["anisotropy_db"] = nullptr;
  }
  return j;
}

json file_json(const FileStats& s) {
  json chi2 = nullptr;
  if (s.chi2.valid)
    chi2 = {{"statistic", round_sig9(s.chi2.statistic)},
            {"dof", s.chi2.dof},
            {"bins_per_axis", s.chi2.bins_per_axis},
            {"bins", s.chi2.bins},
            {"expected_per_bin", round_sig9(s.chi2.expected)}};
  const bool defined = std::isfinite(s.disk_radius);
  json center = json::array();
  for (double c : s.empty.center) center.push_back(round_sig9(c));
  json j = {
      {"file", s.file},
      {"count", s.count},
      {"dim", s.dim},
      {"min_distance", round_sig9(s.min_distance)},
      {"max_packing_distance", round_sig9(max_packing_distance(int64_t(s.count), s.dim))},
      {"relative_radius", round_sig9(s.relative_radius)},
      {"max_empty_radius", round_sig9(s.empty.radius)},
      {"max_empty_center", center},
      {"max_empty_method", s.empty.method},
      {"max_empty_exact", s.empty.exact},
      {"disk_radius", round_sig9(s.disk_radius)},
      {"disk_radius_source", s.disk_radius_from_csv ? "radius column (smallest)" : "min distance"},
      // Undefined for a single point without a radius column (no distance to compare with).
      {"coverage_ratio", defined ? json(round_sig9(s.empty.radius / s.disk_radius)) : json(nullptr)},
      {"maximal", defined ? json(s.maximal) : json(nullptr)},
      {"chi2_p", s.chi2.valid ? json(round_sig9(s.chi2.p)) : json(nullptr)},
      {"chi2", chi2},
  };
  if (!s.empty.exact) j["max_empty_probes"] = s.empty.probes;
  return j;
}

}  // namespace

void check_same_dim(std::span<const PointSet> sets, std::span<const std::string> names) {
  for (std::size_t i = 1; i < sets.size(); ++i)
    if (sets[i].dim != sets[0].dim)
      throw InputError(names[i] + ":1: " + std::to_string(sets[i].dim) + " coordinate columns, but " + names[0] +
                       " has " + std::to_string(sets[0].dim) + " (all files must have the same dim)");
}

int resolve_resolution(std::span<const PointSet> sets, std::optional<int> requested) {
  const int sd = spectral_dim_for(sets.front().dim);
  if (!requested) {
    double mean = 0.0;
    for (const auto& s : sets) mean += double(s.size());
    return default_periodogram_resolution(sd, mean / double(sets.size()));
  }
  const int lo = min_periodogram_resolution(sd), hi = max_periodogram_resolution(sd);
  if (*requested < lo || *requested > hi || *requested % 2 != 0)
    throw UsageError("--resolution must be an even number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                     " for " + std::to_string(sd) + "-D spectra, got " + std::to_string(*requested));
  return *requested;
}

FileStats analyze_point_set(const PointSet& points, const std::string& name, bool periodic) {
  FileStats s;
  s.file = name;
  s.count = points.size();
  s.dim = points.dim;
  s.min_distance = min_distance(points, periodic);
  s.relative_radius = relative_radius(s.min_distance, s.count, s.dim);
  s.empty = max_empty_ball(points, periodic);
  s.disk_radius_from_csv = points.has_radius();
  s.disk_radius =
      s.disk_radius_from_csv ? *std::min_element(points.radius.begin(), points.radius.end()) : s.min_distance;
  // Maximal: no point of the domain is farther than disk_radius from every sample. The
  // tolerance covers CSVs rounded to 9 significant digits (pdrt's own are exact since issue 13).
  const double tolerance = 1e-6 * s.disk_radius + 2e-9 * std::sqrt(double(s.dim));
  s.maximal = s.empty.radius <= s.disk_radius + tolerance;
  s.chi2 = chi_square_uniformity(points);
  return s;
}

Analysis analyze_point_sets(std::span<const PointSet> sets, std::span<const std::string> names,
                            const AnalysisOptions& options) {
  Analysis a;
  const int resolution =
      resolve_resolution(sets, options.resolution ? std::optional<int>(options.resolution) : std::nullopt);
  std::vector<FileStats> stats;
  for (std::size_t i = 0; i < sets.size(); ++i) stats.push_back(analyze_point_set(sets[i], names[i], options.periodic));

  a.periodogram = compute_periodogram(sets, resolution);
  const Periodogram& pg = a.periodogram;
  const int K = pg.realizations;
  json spectrum = {
      {"spectral_dim", pg.spectral_dim},
      {"projection", pg.spectral_dim == 2 ? json::array({0, 1}) : json::array({0})},
      {"resolution", pg.resolution},
      {"realizations", K},
      {"mean_count", round_sig9(pg.mean_count)},
      {"nyquist_frequency", pg.resolution / 2},
      {"normalization", "|FFT|^2 / N per realization, averaged; white noise = 1; DC set to 0"},
      {"frequency_unit",
       "frequency: cycles per unit length; frequency_normalized: frequency / mean_count^(1/spectral_dim), "
       "i.e. in units of the mean sample spacing"},
      {"db",
       "10*log10 of power (and of anisotropy s^2/P^2): white noise power 1 = 0 dB; McCool & Fiume 1992 "
       "section 2 write -20*log10(x)"},
      {"anisotropy_white_noise_db",
       pg.spectral_dim == 2 ? json(round_sig9(-10.0 * std::log10(double(K)))) : json(nullptr)},
      {"annuli", radial_json(equal_annuli(pg, 20), pg)},
      {"fine_annuli", radial_json(fine_annuli(pg), pg)},
  };

  json& j = a.stats;
  j = file_json(stats.front());
  j["files"] = json::array();
  for (const auto& s : stats) j["files"].push_back(s.file);
  j["periodic"] = options.periodic;
  j["realizations"] = K;
  j["prefix_relative_radius"] = rounded(prefix_relative_radius(sets.front(), options.periodic));
  j["prefix_relative_radius_first_n"] = 2;
  j["per_file"] = json::array();
  for (const auto& s : stats) j["per_file"].push_back(file_json(s));
  j["spectrum"] = spectrum;
  j["pdrt_version"] = PDRT_VERSION;
  return a;
}

}  // namespace pdrt
