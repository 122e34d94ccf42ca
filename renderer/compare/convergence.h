#pragma once
// Error-versus-cost curves of `pdrt compare` (RMSE against samples or seconds), read on
// log-log axes where Monte Carlo convergence is a straight line.
#include <vector>

namespace pdrt {

// Least-squares slope of log(y) against log(x), over the points where both are > 0; 0 when
// fewer than two such points.
double loglog_slope(const std::vector<double>& x, const std::vector<double>& y);

// y(x0) interpolated linearly in log-log between points sorted by x; NaN outside their range.
double loglog_interp(const std::vector<double>& x, const std::vector<double>& y, double x0);

// The fewest cost at which the curve (cost[i], error[i]) reaches error <= target: log-log
// interpolation on the first segment that crosses it, after sorting by cost.
struct CostToReach {
  double cost;       // NaN when no point reaches the target
  bool upper_bound;  // the cheapest point already reaches it: the true cost may be lower
};
CostToReach cost_to_reach(const std::vector<double>& cost, const std::vector<double>& error, double target);

}  // namespace pdrt
