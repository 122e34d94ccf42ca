#pragma once
// A 1-D hierarchical Poisson-disk sequence whose density is also uniform, for the time
// tables. McCool–Fiume relaxation in 1-D keeps every prefix's radius but splits each gap
// near its middle, so a region's spacing stays its ancestor gap over a power of two and the
// density never evens out (Kuiper discrepancy ~0.08 at every prefix, docs/results.md).
// Here each point is still a dart in the free space at the current radius, but the radius
// is tied to the count (c/n, so every n-prefix has rho >= c) and of several darts the one
// in the emptiest neighbourhood over several scales is kept (McCool §4's "best-fitting"
// candidate with density as the fit).
#include "sampling/core/point_set.h"

#include <cstdint>

namespace pdrt {

struct BalancedRelaxation1D {
  int64_t count = 1024;
  uint64_t seed = 1;
  double prefix_rho = 0.66;  // every prefix: min gap >= prefix_rho / n
  double full_rho = 0.73;    // and >= full_rho / count, so the whole set reaches it
  int candidates = 32;       // darts per point
  int finest_window = 4;     // smallest neighbourhood scored, in expected points
  bool periodic = true;      // the circle (tables); else [0, 1) with walls
};

// Points in [0, 1) in rank order; radius[i] is the minimum distance of the (i+1)-prefix
// (non-increasing). Throws UsageError for count < 1.
PointSet balanced_relaxation_1d(const BalancedRelaxation1D& p);

}  // namespace pdrt
