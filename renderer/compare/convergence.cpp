#include "renderer/compare/convergence.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pdrt {

double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] > 0 && y[i] > 0)) continue;
    double a = std::log(x[i]), b = std::log(y[i]);
    n += 1, sx += a, sy += b, sxx += a * a, sxy += a * b;
  }
  double d = n * sxx - sx * sx;
  return n >= 2 && d != 0 ? (n * sxy - sx * sy) / d : 0.0;
}

double loglog_interp(const std::vector<double>& x, const std::vector<double>& y, double x0) {
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    if (x0 >= x[i] && x0 <= x[i + 1] && x[i] > 0 && x[i + 1] > x[i] && y[i] > 0 && y[i + 1] > 0) {
      double t = (std::log(x0) - std::log(x[i])) / (std::log(x[i + 1]) - std::log(x[i]));
      return std::exp(std::log(y[i]) + t * (std::log(y[i + 1]) - std::log(y[i])));
    }
  }
  return std::nan("");
}

CostToReach cost_to_reach(const std::vector<double>& cost, const std::vector<double>& error, double target) {
  std::vector<std::size_t> order(std::min(cost.size(), error.size()));
  std::iota(order.begin(), order.end(), 0);
  order.erase(std::remove_if(order.begin(), order.end(), [&](std::size_t i) { return !(cost[i] > 0 && error[i] > 0); }),
              order.end());
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] < cost[b]; });
  if (order.empty() || !(target > 0)) return {std::nan(""), false};
  if (error[order[0]] <= target) return {cost[order[0]], true};
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    const double c0 = cost[order[k]], c1 = cost[order[k + 1]];
    const double e0 = error[order[k]], e1 = error[order[k + 1]];
    if (e1 > target) continue;
    // e0 > target >= e1: the crossing lies on this segment.
    const double t = (std::log(target) - std::log(e0)) / (std::log(e1) - std::log(e0));
    return {std::exp(std::log(c0) + t * (std::log(c1) - std::log(c0))), false};
  }
  return {std::nan(""), false};
}

}  // namespace pdrt
