// Packing densities and the count <-> radius mapping of Gamito–Maddock §4.6.
#include "sampling/generators/generator.h"

#include <cmath>
#include <numbers>

namespace pdrt {
namespace {

// Volume of the unit ball in `dim` dimensions: pi^(n/2) / Gamma(n/2 + 1).
double unit_ball_volume(int dim) { return std::pow(std::numbers::pi, dim / 2.0) / std::tgamma(dim / 2.0 + 1.0); }

// Diameter d (= pdrt radius) for which n balls of diameter d fill `density` of the unit cube.
double distance_for_density(double n, int dim, double density) {
  double r = std::pow(density / (n * unit_ball_volume(dim)), 1.0 / dim);
  return 2.0 * r;
}

}  // namespace

double densest_packing_density(int dim) {
  constexpr double pi = std::numbers::pi;
  switch (dim) {
    case 1:
      return 1.0;
    case 2:
      return pi / std::sqrt(12.0);
    case 3:
      return pi / std::sqrt(18.0);
    case 4:
      return pi * pi / 16.0;
    case 5:
      return pi * pi / (15.0 * std::sqrt(2.0));
    case 6:
      return pi * pi * pi / (48.0 * std::sqrt(3.0));
    case 7:
      return pi * pi * pi / 105.0;
    default:
      return pi * pi * pi * pi / 384.0;
  }
}

double max_packing_distance(int64_t n, int dim) {
  return distance_for_density(double(n), dim, densest_packing_density(dim));
}

double maximal_packing_density(int dim) {
  // 2-D..4-D: Gamito–Maddock Table I. 1-D: Renyi's parking constant. 5-D..8-D: random
  // sequential addition saturation densities (Torquato, Uche & Stillinger 2006).
  switch (dim) {
    case 1:
      return 0.7476;
    case 2:
      return 0.5470;
    case 3:
      return 0.3841;
    case 4:
      return 0.2599;
    case 5:
      return 0.1707;
    case 6:
      return 0.1097;
    case 7:
      return 0.0687;
    default:
      return 0.0427;
  }
}

double radius_for_count(int64_t n_wanted, int dim, bool periodic) {
  double n = double(n_wanted);
  if (!periodic && dim >= 2 && dim <= 5) {
    // Eq. (7): N' = N + alpha N^(beta+1); solve for N given N' (Table II for 2-D..4-D; 5-D:
    // beta extrapolated from Table II's trend, alpha fitted by pdrt to gamito at N = 2000).
    static constexpr double alpha[] = {1.0997, 2.2119, 4.1114, 7.2};
    static constexpr double beta[] = {-0.4999, -0.3538, -0.3056, -0.28};
    double a = alpha[dim - 2], b = beta[dim - 2], target = n, x = 1.0;
    for (int it = 0; it < 100; ++it) {
      double f = x + a * std::pow(x, b + 1.0) - target;
      double df = 1.0 + a * (b + 1.0) * std::pow(x, b);
      double next = x - f / df;
      if (next <= 0.0) next = x / 2.0;
      if (std::abs(next - x) < 1e-9 * std::max(1.0, x)) {
        x = next;
        break;
      }
      x = next;
    }
    n = std::max(1.0, x);
  }
  return distance_for_density(n, dim, maximal_packing_density(dim));
}

double expected_count_for_radius(double radius, int dim) {
  double r = radius / 2.0;
  return maximal_packing_density(dim) / (unit_ball_volume(dim) * std::pow(r, dim));
}

}  // namespace pdrt
