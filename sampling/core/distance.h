#pragma once
// Euclidean and toroidal (periodic) squared distances in [0,1)^dim.
#include <cmath>
#include <span>

namespace pdrt {

// Signed per-axis difference a - b of coordinates in [0,1), wrapped to [-0.5, 0.5] when
// periodic (branches instead of nearbyint: this sits in every neighbour query).
inline double axis_delta(double a, double b, bool periodic) {
  double d = a - b;
  if (periodic) {
    if (d > 0.5)
      d -= 1.0;
    else if (d < -0.5)
      d += 1.0;
  }
  return d;
}

inline double distance_sq(const double* a, const double* b, int dim, bool periodic) {
  double s = 0.0;
  for (int k = 0; k < dim; ++k) {
    double d = axis_delta(a[k], b[k], periodic);
    s += d * d;
  }
  return s;
}

inline double distance_sq(std::span<const double> a, std::span<const double> b, bool periodic) {
  return distance_sq(a.data(), b.data(), int(a.size()), periodic);
}

}  // namespace pdrt
