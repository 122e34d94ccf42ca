#pragma once
// The one contract every point-set generator in pdrt follows:
//   generate(method, dim, count-or-radius, seed, periodic) -> points in [0,1)^dim
// in generation order, plus each point's radius at placement where the method has one.
// "radius" is always the minimum distance between points (Gamito–Maddock's r is half of it);
// periodic means toroidal distance on the unit cube.
#include "sampling/core/int_range.h"
#include "sampling/core/point_set.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pdrt {

inline constexpr IntRange kLloydIterationsRange{0, 10000};
inline constexpr int64_t kOwenPoissonMaxCount = 65536;  // owen-pd: 2^16 Sobol points; pmj02bn too

struct GeneratorParams {
  std::string method = "gamito";
  int dim = 2;
  std::optional<int64_t> count;  // exactly one of count / radius (method permitting)
  std::optional<double> radius;  // minimum distance between points
  uint64_t seed = 1;
  bool periodic = false;
  // Method tuning; unset means the method's documented default.
  // dart: consecutive failures before stopping (1000); bridson: candidates k per active
  // point (30); mccool: consecutive missed darts before the radius shrinks
  // (30 + magnification x placed, McCool §4); best-candidate:
  // candidates per placed point m (1); lloyd: Monte Carlo probes per site (64); balanced:
  // darts per placed point, the best kept (32); stratified-bc: candidates per point (16);
  // stratified-pd: open intervals tried per point (64); pmj02bn: candidates per point (10).
  std::optional<int64_t> attempts;
  std::optional<double> decay;          // mccool: radius multiplier per step, in (0,1) (0.97)
  std::optional<double> magnification;  // mccool: extra missed darts allowed per placed point (128)
  std::optional<double> start_radius;   // mccool: initial radius (default: see mccool_fiume.cpp)
  int lloyd_iterations = 10;            // lloyd
  bool quiet = true;                    // generators may report progress on stderr when false
};

struct MethodInfo {
  std::string name;
  std::string summary;
  int max_dim;
  bool accepts_count;
  bool accepts_radius;
  bool records_radius;  // output carries a radius column
};

const std::vector<MethodInfo>& methods();
const MethodInfo* find_method(const std::string& name);

// Checks every parameter (method, dim, count/radius ranges, memory estimate) and throws
// UsageError naming the offending argument. generate() calls it first.
void validate(const GeneratorParams& p);

PointSet generate(const GeneratorParams& p);

// Densest-packing minimum distance for n points in the unit cube of `dim` dimensions
// (2-D hexagonal), from Gamito–Maddock Eq. (5) with pdrt's radius = 2r.
double max_packing_distance(int64_t n, int dim);

// Densest known sphere packing density per dimension (Conway & Sloane; 2-D hexagonal, 1-D 1).
double densest_packing_density(int dim);

// Gamito–Maddock Table I average packing density of a maximal set (periodic), per dimension.
double maximal_packing_density(int dim);

// Minimum distance that gives about `n` points in a maximal set: Eq. (6), and for
// non-periodic domains the boundary correction of Eq. (7) (solved by Newton–Raphson).
double radius_for_count(int64_t n, int dim, bool periodic);

// Expected point count of a maximal set at minimum distance `radius` (inverse of Eq. (6)).
double expected_count_for_radius(double radius, int dim);

// Individual generators (one file each). All assume validated parameters.
PointSet generate_random(const GeneratorParams& p);
PointSet generate_jitter(const GeneratorParams& p);
PointSet generate_dart(const GeneratorParams& p);
PointSet generate_mccool(const GeneratorParams& p);
PointSet generate_bridson(const GeneratorParams& p);
PointSet generate_gamito(const GeneratorParams& p);
PointSet generate_lloyd(const GeneratorParams& p);
PointSet generate_best_candidate(const GeneratorParams& p);
PointSet generate_balanced(const GeneratorParams& p);
PointSet generate_stratified_bc(const GeneratorParams& p);
PointSet generate_stratified_pd(const GeneratorParams& p);
PointSet generate_owen_pd(const GeneratorParams& p);
PointSet generate_pmj02bn(const GeneratorParams& p);

}  // namespace pdrt
