#include "sampling/samplers/rank_threshold.h"

#include "sampling/core/errors.h"

#include <cmath>

namespace pdrt {

RankSelection rank_threshold(std::span<const Vec2> candidates, const std::function<double(Vec2)>& f, double f_min,
                             double f_max, std::optional<double> x_integral) {
  if (!(f_max > f_min)) throw UsageError("rank_threshold: max f must exceed min f");
  RankSelection out;
  const double n = double(candidates.size()), span = f_max - f_min;
  std::vector<double> x_kept;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    double x = (f(candidates[i]) - f_min) / span;
    // McCool §5.2 rank threshold; ranks are 1-based: r = i/n with 1 <= i <= n.
    if (double(i + 1) / n <= x) {
      out.kept.push_back(uint32_t(i));
      x_kept.push_back(x);
    }
  }
  const double k = double(out.kept.size());
  out.x_integral = x_integral.value_or(k / n);
  out.weight.resize(out.kept.size());
  for (std::size_t j = 0; j < out.kept.size(); ++j) out.weight[j] = out.x_integral / (k * x_kept[j]);
  return out;
}

}  // namespace pdrt
