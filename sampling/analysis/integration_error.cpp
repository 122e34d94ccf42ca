#include "sampling/analysis/integration_error.h"

#include <cmath>
#include <numbers>

namespace pdrt {

const std::vector<Integrand>& standard_integrands() {
  static const double gauss_side = std::sqrt(std::numbers::pi) / 2 * std::erf(1.0);
  static const std::vector<Integrand> list = {
      {"disk", [](Vec2 p) { return p[0] * p[0] + p[1] * p[1] < 2 / std::numbers::pi ? 1.0 : 0.0; }, 0.5},
      {"triangle", [](Vec2 p) { return p[1] > p[0] ? 1.0 : 0.0; }, 0.5},
      {"step", [](Vec2 p) { return p[0] < 1 / std::numbers::pi ? 1.0 : 0.0; }, 1 / std::numbers::pi},
      {"gaussian", [](Vec2 p) { return std::exp(-p[0] * p[0] - p[1] * p[1]); }, gauss_side * gauss_side},
      {"bilinear", [](Vec2 p) { return p[0] * p[1]; }, 0.25},
  };
  return list;
}

namespace {

// RMS error against `exact` of the N-sample mean of value(pixel stream t, sample i) over
// `trials` pixel streams.
template <class Value>
double rmse_over_trials(int64_t n, int trials, double exact, Value&& value) {
  double err2 = 0.0;
  for (int t = 0; t < trials; ++t) {
    double sum = 0.0;
    for (int64_t i = 0; i < n; ++i) sum += value(t, i);
    double e = sum / double(n) - exact;
    err2 += e * e;
  }
  return std::sqrt(err2 / trials);
}

}  // namespace

double integration_rmse(const Sampler& s, const Integrand& f, int64_t n, int trials, Family family) {
  return rmse_over_trials(n, trials, f.exact,
                          [&](int t, int64_t i) { return f.f(s.get_2d(t % 64, t / 64, i, family, 0)); });
}

const std::vector<Integrand1D>& time_integrands() {
  static const std::vector<Integrand1D> list = {
      {"step", [](double t) { return t < 1 / std::numbers::pi ? 1.0 : 0.0; }, 1 / std::numbers::pi},
      {"exponential", [](double t) { return std::exp(-t); }, 1 - std::exp(-1.0)},
  };
  return list;
}

double integration_rmse_1d(const Sampler& s, const Integrand1D& f, int64_t n, int trials) {
  return rmse_over_trials(n, trials, f.exact,
                          [&](int t, int64_t i) { return f.f(s.get_1d(t % 64, t / 64, i, Family::Time, 0)); });
}

}  // namespace pdrt
