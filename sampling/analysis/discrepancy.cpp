#include "sampling/analysis/discrepancy.h"

#include <algorithm>

namespace pdrt {

double periodic_discrepancy_1d(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double n = double(values.size());
  double above = 0.0, below = 0.0;  // max(F_n - F) just after a point, max(F - F_n) just before
  for (std::size_t i = 0; i < values.size(); ++i) {
    above = std::max(above, double(i + 1) / n - values[i]);
    below = std::max(below, values[i] - double(i) / n);
  }
  return above + below;
}

}  // namespace pdrt
