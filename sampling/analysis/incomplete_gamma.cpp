#include "sampling/analysis/incomplete_gamma.h"

#include <cmath>
#include <limits>

namespace pdrt {
namespace {

constexpr double kEps = 1e-16;
constexpr int kMaxIterations = 10'000'000;  // both expansions need O(sqrt(a)) terms near x = a

// log of x^a e^-x / Gamma(a), the common prefactor.
double log_prefactor(double a, double x) { return a * std::log(x) - x - std::lgamma(a); }

// P(a, x) by its power series, for x < a + 1.
double series_p(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * kEps) break;
  }
  return sum * std::exp(log_prefactor(a, x));
}

// Q(a, x) by its continued fraction (modified Lentz), for x >= a + 1.
double continued_fraction_q(double a, double x) {
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kEps) break;
  }
  return std::exp(log_prefactor(a, x)) * h;
}

}  // namespace

double regularized_gamma_q(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return 1.0;
  if (std::isinf(x)) return 0.0;
  return x < a + 1.0 ? 1.0 - series_p(a, x) : continued_fraction_q(a, x);
}

double regularized_gamma_p(double a, double x) {
  if (!(a > 0.0) || !(x >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return 0.0;
  if (std::isinf(x)) return 1.0;
  return x < a + 1.0 ? series_p(a, x) : 1.0 - continued_fraction_q(a, x);
}

double chi_square_p_value(double statistic, double dof) { return regularized_gamma_q(0.5 * dof, 0.5 * statistic); }

}  // namespace pdrt
