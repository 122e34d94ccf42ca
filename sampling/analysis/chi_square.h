#pragma once
// Chi-square test of uniformity: counts on a regular grid of b^dim cells against the uniform
// expectation N / b^dim, with b the largest per-axis count keeping that expectation >= 5.
#include "sampling/core/point_set.h"

#include <cstdint>

namespace pdrt {

struct ChiSquare {
  bool valid = false;  // false when N < 10 (fewer than two cells with 5 expected)
  int bins_per_axis = 0;
  int64_t bins = 0;
  double expected = 0.0;  // per cell
  double statistic = 0.0;
  int64_t dof = 0;  // bins - 1
  double p = 0.0;   // upper tail: small = clumped; near 1 = more even than random
};

ChiSquare chi_square_uniformity(const PointSet& points);

}  // namespace pdrt
