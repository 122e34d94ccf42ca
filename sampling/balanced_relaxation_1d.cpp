#include "balanced_relaxation_1d.h"

#include "errors.h"
#include "rng.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pdrt {
namespace {

// Points of sorted `x` in the arc [lo, lo + w) of the circle, 0 < w <= 1.
std::size_t count_in_arc(const std::vector<double>& x, double lo, double w) {
  lo -= std::floor(lo);
  const double hi = lo + w;
  auto at = [&](double v) { return std::size_t(std::lower_bound(x.begin(), x.end(), v) - x.begin()); };
  if (hi <= 1.0) return at(hi) - at(lo);
  return x.size() - at(lo) + at(hi - 1.0);
}

}  // namespace

PointSet balanced_relaxation_1d(const BalancedRelaxation1D& p) {
  if (p.count < 1) throw UsageError("balanced relaxation: count must be >= 1");
  Rng rng(p.seed, 0x62616c31);
  PointSet ps;
  ps.dim = 1;
  ps.periodic = true;
  ps.coords.reserve(std::size_t(p.count));
  ps.radius.reserve(std::size_t(p.count));
  std::vector<double> sorted;  // the placed points in increasing order
  sorted.reserve(std::size_t(p.count));
  const double first = rng.uniform();
  ps.coords.push_back(first);
  ps.radius.push_back(0.5);  // the largest distance on the circle
  sorted.push_back(first);

  std::vector<double> win_lo, win_cum;  // free windows: start and running total of lengths
  std::vector<double> darts(std::size_t(std::max(1, p.candidates)));
  for (int64_t n = 2; n <= p.count; ++n) {
    const std::size_t have = sorted.size();
    // Radius for the n-prefix: rho >= prefix_rho, and >= full_rho for the whole set.
    const double m = std::max(p.prefix_rho, p.full_rho * double(n) / double(p.count)) / double(n);
    win_lo.clear();
    win_cum.clear();
    double total = 0, largest = -1, largest_mid = 0;
    for (std::size_t i = 0; i < have; ++i) {
      const double a = sorted[i], b = i + 1 < have ? sorted[i + 1] : sorted[0] + 1.0, g = b - a;
      if (g > largest) largest = g, largest_mid = a + 0.5 * g;
      if (g > 2 * m) {
        win_lo.push_back(a + m);
        total += g - 2 * m;
        win_cum.push_back(total);
      }
    }
    double x;
    if (win_lo.empty()) {
      x = largest_mid;  // no room at this radius: the split that loses the least
    } else {
      for (double& d : darts) {
        const double u = rng.uniform() * total;
        const std::size_t w = std::min(std::size_t(std::upper_bound(win_cum.begin(), win_cum.end(), u) - win_cum.begin()),
                                       win_lo.size() - 1);
        d = win_lo[w] + (u - (w ? win_cum[w - 1] : 0.0));
      }
      // Score: relative deficit of points in arcs of width 1/2, 1/4, ... centred on the dart.
      double best = -1e300;
      x = darts[0];
      for (double d : darts) {
        double score = 0;
        for (double w = 0.5; w * double(have) >= double(p.finest_window); w *= 0.5) {
          const double expected = w * double(have);
          score += (expected - double(count_in_arc(sorted, d - 0.5 * w, w))) / expected;
        }
        if (score > best) best = score, x = d;
      }
    }
    x -= std::floor(x);
    if (x >= 1.0) x = 0.0;
    auto it = std::lower_bound(sorted.begin(), sorted.end(), x);
    const double left = it == sorted.begin() ? sorted.back() - 1.0 : *(it - 1);
    const double right = it == sorted.end() ? sorted.front() + 1.0 : *it;
    sorted.insert(it, x);
    ps.coords.push_back(x);
    ps.radius.push_back(std::min({ps.radius.back(), x - left, right - x}));
  }
  return ps;
}

}  // namespace pdrt
