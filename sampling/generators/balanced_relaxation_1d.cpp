#include "sampling/generators/balanced_relaxation_1d.h"

#include "sampling/core/errors.h"
#include "sampling/generators/generator.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pdrt {
namespace {

// Points of sorted `x` in [lo, lo + w), 0 < w <= 1: an arc of the circle when periodic,
// else the part of it inside [0, 1). Sets `width` to the length counted.
std::size_t count_in_arc(const std::vector<double>& x, double lo, double w, bool periodic, double& width) {
  auto at = [&](double v) { return std::size_t(std::lower_bound(x.begin(), x.end(), v) - x.begin()); };
  if (!periodic) {
    const double a = std::max(lo, 0.0), b = std::min(lo + w, 1.0);
    width = b - a;
    return at(b) - at(a);
  }
  width = w;
  lo -= std::floor(lo);
  const double hi = lo + w;
  if (hi <= 1.0) return at(hi) - at(lo);
  return x.size() - at(lo) + at(hi - 1.0);
}

}  // namespace

PointSet balanced_relaxation_1d(const BalancedRelaxation1D& p) {
  if (p.count < 1) throw UsageError("balanced relaxation: count must be >= 1");
  Rng rng(p.seed, 0x62616c31);
  PointSet ps;
  ps.dim = 1;
  ps.periodic = p.periodic;
  ps.coords.reserve(std::size_t(p.count));
  ps.radius.reserve(std::size_t(p.count));
  std::vector<double> sorted;  // the placed points in increasing order
  sorted.reserve(std::size_t(p.count));
  const double first = rng.uniform();
  ps.coords.push_back(first);
  ps.radius.push_back(p.periodic ? 0.5 : 1.0);  // the largest distance in the domain
  sorted.push_back(first);

  std::vector<double> win_lo, win_cum;  // free windows: start and running total of lengths
  std::vector<double> darts(std::size_t(std::max(1, p.candidates)));
  for (int64_t n = 2; n <= p.count; ++n) {
    const std::size_t have = sorted.size();
    // Radius for the n-prefix: rho >= prefix_rho, and >= full_rho for the whole set.
    const double m = std::max(p.prefix_rho, p.full_rho * double(n) / double(p.count)) / double(n);
    win_lo.clear();
    win_cum.clear();
    double total = 0, best_gain = -1, best_at = 0;  // fallback: the farthest free position
    auto window = [&](double lo, double len) {
      win_lo.push_back(lo);
      total += len;
      win_cum.push_back(total);
    };
    for (std::size_t i = 0; i + (p.periodic ? 0 : 1) < have; ++i) {
      const double a = sorted[i], b = i + 1 < have ? sorted[i + 1] : sorted[0] + 1.0, g = b - a;
      if (0.5 * g > best_gain) best_gain = 0.5 * g, best_at = a + 0.5 * g;
      if (g > 2 * m) window(a + m, g - 2 * m);
    }
    if (!p.periodic) {  // the walls: a point may sit on 0 (and just below 1)
      const double left = sorted.front(), right = 1.0 - sorted.back();
      if (left > best_gain) best_gain = left, best_at = 0.0;
      if (right > best_gain) best_gain = right, best_at = std::nextafter(1.0, 0.0);
      if (left > m) window(0.0, left - m);
      if (right > m) window(sorted.back() + m, right - m);
    }
    double x;
    if (win_lo.empty()) {
      x = best_at;  // no room at this radius: the placement that loses the least
    } else {
      for (double& d : darts) {
        const double u = rng.uniform() * total;
        const std::size_t w = std::min(
            std::size_t(std::upper_bound(win_cum.begin(), win_cum.end(), u) - win_cum.begin()), win_lo.size() - 1);
        d = win_lo[w] + (u - (w ? win_cum[w - 1] : 0.0));
      }
      // Score: relative deficit of points in arcs of width 1/2, 1/4, ... centred on the dart.
      double best = -1e300;
      x = darts[0];
      for (double d : darts) {
        double score = 0;
        for (double w = 0.5; w * double(have) >= double(p.finest_window); w *= 0.5) {
          double width;
          const double got = double(count_in_arc(sorted, d - 0.5 * w, w, p.periodic, width));
          const double expected = width * double(have);
          score += (expected - got) / expected;
        }
        if (score > best) best = score, x = d;
      }
    }
    x -= std::floor(x);
    if (x >= 1.0) x = 0.0;
    auto it = std::lower_bound(sorted.begin(), sorted.end(), x);
    double near = ps.radius.back();
    if (it != sorted.begin())
      near = std::min(near, x - *(it - 1));
    else if (p.periodic)
      near = std::min(near, x - (sorted.back() - 1.0));
    if (it != sorted.end())
      near = std::min(near, *it - x);
    else if (p.periodic)
      near = std::min(near, sorted.front() + 1.0 - x);
    sorted.insert(it, x);
    ps.coords.push_back(x);
    ps.radius.push_back(near);
  }
  return ps;
}

PointSet generate_balanced(const GeneratorParams& p) {
  BalancedRelaxation1D b;
  b.count = *p.count;
  b.seed = p.seed;
  b.periodic = p.periodic;
  if (p.attempts) b.candidates = int(std::min<int64_t>(*p.attempts, 1 << 20));
  return balanced_relaxation_1d(b);
}

}  // namespace pdrt
