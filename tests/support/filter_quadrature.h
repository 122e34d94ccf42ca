#pragma once
// Midpoint-rule integrals over a pixel filter's square support, for the reconstruction tests.
#include "renderer/render/filter.h"

namespace pdrt::test {

// Integral of h(x, y, f(x, y)) over [-r, r]^2 on n^2 cells.
template <class H>
double filter_quadrature(const Filter& f, H&& h, int n = 800) {
  const double r = f.radius(), d = 2 * r / n;
  double s = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double x = -r + (i + 0.5) * d, y = -r + (j + 0.5) * d;
      s += h(x, y, double(f.eval(float(x), float(y))));
    }
  return s * d * d;
}

// Integral of g(x, y) * f(x, y) over the filter's square.
template <class G>
double filter_integral(const Filter& f, G&& g) {
  return filter_quadrature(f, [&](double x, double y, double v) { return g(x, y) * v; });
}

}  // namespace pdrt::test
