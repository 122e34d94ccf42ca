// Method registry, parameter validation and dispatch for the generator contract.
#include "sampling/generators/generator.h"

#include "sampling/core/errors.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pdrt {

const std::vector<MethodInfo>& methods() {
  static const std::vector<MethodInfo> list = {
      {"random", "uniform random points (the Poisson process baseline)", kMaxDim, true, false, false},
      {"jitter", "jittered grid, one point per cell of the finest k^dim grid <= count (Cook §4)", kMaxDim, true, false,
       false},
      {"dart", "naive dart throwing at a fixed radius with an attempt budget (Cook §3)", kMaxDim, true, true, true},
      {"mccool", "McCool–Fiume relaxation dart throwing, hierarchical, exact count (§4)", kMaxDim, true, false, true},
      {"bridson", "Bridson 2007 fast Poisson-disk sampling, annulus sampled directly", kMaxDim, true, true, true},
      {"gamito", "Gamito–Maddock 2009 accurate maximal sampling with a 2^n-tree", 5, true, true, true},
      {"lloyd", "Lloyd relaxation on the torus from a Poisson-disk start (McCool §6)", kMaxDim, true, false, false},
      {"best-candidate", "Mitchell 1991 best-candidate, hierarchical", kMaxDim, true, false, true},
      {"balanced", "1-D balanced relaxation, hierarchical with even density (the time tables)", 1, true, false, true},
      {"stratified-bc", "1-D progressive jitter, each point the best of m candidates in its stratum", 1, true, false,
       true},
      {"stratified-pd", "2-D (0,2)-first hierarchical Poisson-disk on the torus: strata kept while rho >= 0.65 allows",
       2, true, false, true},
      {"owen-pd",
       "2-D Owen-scrambled Sobol, scramble annealed for Poisson-disk prefixes ((0,m,2)-nets; periodic, count <= 65536)",
       2, true, false, true},
      {"pmj02bn",
       "2-D progressive multi-jittered (0,2), the best of m candidates per point (Christensen et al. 2018; periodic, "
       "count <= 65536)",
       2, true, false, true},
  };
  return list;
}

const MethodInfo* find_method(const std::string& name) {
  for (const auto& m : methods())
    if (m.name == name) return &m;
  return nullptr;
}

namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(9);
  s << v;
  return s.str();
}

double memory_budget_bytes() {
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  double phys = (pages > 0 && page > 0) ? double(pages) * double(page) : 8.0 * (1ull << 30);
  return 0.5 * phys;
}

// Rough bytes per point each method needs at its peak (points, grids, trees).
double bytes_per_point(const std::string& method, int dim) {
  double base = 8.0 * (dim + 1) + 32.0;
  // gamito's cells and grids: peak resident memory measured at ~50 B/point in 1-D, ~150 B in
  // 2-D, ~630 B in 3-D, ~3 KB in 4-D and ~17 KB in 5-D (10^6, 10^6, 10^5, 2x10^4, 10^4
  // points), with a margin.
  if (method == "gamito") {
    static constexpr double tree[] = {100, 250, 1000, 5000, 30000};
    return base + tree[std::clamp(dim, 1, 5) - 1];
  }
  if (method == "lloyd") return base * 4.0;
  return base * 2.0;
}

}  // namespace

void validate(const GeneratorParams& p) {
  const MethodInfo* m = find_method(p.method);
  if (!m) {
    std::string known;
    for (const auto& x : methods()) {
      if (!known.empty()) known += ", ";
      known += x.name;
    }
    throw UsageError("--method: unknown method '" + p.method + "' (known: " + known + ")");
  }
  if (p.method == "owen-pd" || p.method == "pmj02bn") {  // 2-D constructions on the torus, at most 2^16 points
    if (p.dim != 2) throw UsageError("--dim must be 2 for method '" + p.method + "', got " + std::to_string(p.dim));
    if (!p.periodic)
      throw UsageError("--periodic is required for method '" + p.method + "' (its distances are toroidal)");
    if (p.count && *p.count > kOwenPoissonMaxCount)
      throw UsageError("--count must be at most " + std::to_string(kOwenPoissonMaxCount) + " for method '" + p.method +
                       "', got " + std::to_string(*p.count));
  }
  if (p.dim < 1 || p.dim > m->max_dim)
    throw UsageError("--dim must be between 1 and " + std::to_string(m->max_dim) + " for method '" + p.method +
                     "', got " + std::to_string(p.dim));
  if (p.method == "stratified-pd") {  // a 2-D construction on the torus
    if (p.dim != 2) throw UsageError("--dim must be 2 for method 'stratified-pd', got " + std::to_string(p.dim));
    if (!p.periodic) throw UsageError("--periodic is required for method 'stratified-pd' (its distances are toroidal)");
  }
  if (p.count && p.radius) throw UsageError("--count and --radius are mutually exclusive; give one");
  if (!p.count && !p.radius) throw UsageError("one of --count or --radius is required");
  if (p.count && !m->accepts_count)
    throw UsageError("--count is not accepted by method '" + p.method + "'; use --radius");
  if (p.radius && !m->accepts_radius)
    throw UsageError("--radius is not accepted by method '" + p.method + "'; use --count");

  double expected = 0.0;
  if (p.count) {
    if (*p.count <= 0) throw UsageError("--count must be > 0, got " + std::to_string(*p.count));
    expected = double(*p.count);
  } else {
    double r = *p.radius;
    if (!std::isfinite(r) || r <= 0.0) throw UsageError("--radius must be a finite number > 0, got " + fmt(r));
    double diameter = std::sqrt(double(p.dim)) * (p.periodic ? 0.5 : 1.0);
    if (r >= diameter)
      throw UsageError("--radius " + fmt(r) + " is too large: no two points fit (the " +
                       std::string(p.periodic ? "periodic " : "") + "domain's diameter is " + fmt(diameter) + ")");
    expected = expected_count_for_radius(r, p.dim);
  }
  double need = expected * bytes_per_point(p.method, p.dim), budget = memory_budget_bytes();
  if (!(need <= budget) || expected > 2.0e9)
    throw UsageError(std::string(p.count ? "--count " : "--radius ") +
                     (p.count ? std::to_string(*p.count) : fmt(*p.radius)) + " needs about " +
                     fmt(std::round(need / double(1ull << 30) * 10) / 10) + " GiB for ~" + fmt(expected) +
                     " points, more than the " + fmt(std::round(budget / double(1ull << 30))) + " GiB limit");

  if (p.attempts && *p.attempts <= 0) throw UsageError("--attempts must be > 0, got " + std::to_string(*p.attempts));
  if (p.decay && !(*p.decay > 0.0 && *p.decay < 1.0))
    throw UsageError("--decay must be in (0, 1), got " + fmt(*p.decay));
  if (p.magnification && !(std::isfinite(*p.magnification) && *p.magnification >= 0.0))
    throw UsageError("--magnification must be a finite number >= 0, got " + fmt(*p.magnification));
  if (p.start_radius && !(std::isfinite(*p.start_radius) && *p.start_radius > 0.0))
    throw UsageError("--start-radius must be > 0, got " + fmt(*p.start_radius));
  if (p.lloyd_iterations < 0 || !kLloydIterationsRange.contains(uint64_t(p.lloyd_iterations)))
    throw UsageError("--iterations must be an integer in " + kLloydIterationsRange.str() + ", got " +
                     std::to_string(p.lloyd_iterations));
}

PointSet generate(const GeneratorParams& p) {
  validate(p);
  const std::string& m = p.method;
  PointSet out;
  if (m == "random")
    out = generate_random(p);
  else if (m == "jitter")
    out = generate_jitter(p);
  else if (m == "dart")
    out = generate_dart(p);
  else if (m == "mccool")
    out = generate_mccool(p);
  else if (m == "bridson")
    out = generate_bridson(p);
  else if (m == "gamito")
    out = generate_gamito(p);
  else if (m == "lloyd")
    out = generate_lloyd(p);
  else if (m == "balanced")
    out = generate_balanced(p);
  else if (m == "stratified-bc")
    out = generate_stratified_bc(p);
  else if (m == "stratified-pd")
    out = generate_stratified_pd(p);
  else if (m == "owen-pd")
    out = generate_owen_pd(p);
  else if (m == "pmj02bn")
    out = generate_pmj02bn(p);
  else
    out = generate_best_candidate(p);
  out.dim = p.dim;
  out.periodic = p.periodic;
  return out;
}

}  // namespace pdrt
