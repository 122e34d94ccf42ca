#include "sampling/analysis/chi_square.h"

#include "sampling/analysis/incomplete_gamma.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pdrt {

ChiSquare chi_square_uniformity(const PointSet& points) {
  ChiSquare r;
  const int dim = points.dim;
  const double max_cells = double(points.size()) / 5.0;
  auto cells = [&](int b) { return std::pow(double(b), dim); };
  int b = std::max(1, int(std::floor(std::pow(max_cells, 1.0 / dim))));
  while (cells(b + 1) <= max_cells) ++b;  // guard pow() rounding both ways
  while (b > 1 && cells(b) > max_cells) --b;
  if (cells(b) < 2.0) return r;
  r.valid = true;
  r.bins_per_axis = b;
  r.bins = int64_t(cells(b));
  r.expected = double(points.size()) / double(r.bins);
  r.dof = r.bins - 1;
  std::vector<uint32_t> count(std::size_t(r.bins), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    auto p = points.point(i);
    std::size_t idx = 0;
    for (int k = dim - 1; k >= 0; --k) idx = idx * std::size_t(b) + std::size_t(std::min(int(p[k] * b), b - 1));
    ++count[idx];
  }
  double s = 0.0;
  for (uint32_t c : count) s += (double(c) - r.expected) * (double(c) - r.expected);
  r.statistic = s / r.expected;
  r.p = chi_square_p_value(r.statistic, double(r.dof));
  return r;
}

}  // namespace pdrt
