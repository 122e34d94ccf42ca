// `best-candidate`: Mitchell 1991. The i-th point is the farthest from all earlier points
// among m*i + 1 uniform candidates, so the sequence is hierarchical like McCool–Fiume's.
// The radius column records each point's nearest-neighbour distance at placement.
#include "sampling/generators/generator.h"
#include "sampling/generators/detail/neighbor_grid.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pdrt {

PointSet generate_best_candidate(const GeneratorParams& p) {
  const int dim = p.dim;
  const int64_t n = *p.count, m = p.attempts.value_or(1);
  PointSet ps;
  ps.dim = dim;
  ps.coords.reserve(std::size_t(n) * dim);
  ps.radius.reserve(std::size_t(n));
  Rng rng(p.seed, 0x62657374);
  const double diameter = std::sqrt(double(dim)) * (p.periodic ? 0.5 : 1.0);
  NeighborGrid grid(dim, p.periodic, diameter, std::size_t(n));
  double x[kMaxDim], best[kMaxDim];

  // Exact nearest distance: the grid answers within its reach, a scan beyond it.
  auto nearest_sq = [&](const double* q) {
    double r2 = grid.reach() * grid.reach();
    double d2 = grid.nearest_sq(q, r2);
    if (d2 < r2) return d2;
    d2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < ps.size(); ++i)
      d2 = std::min(d2, distance_sq(q, ps.coords.data() + i * dim, dim, p.periodic));
    return d2;
  };

  for (int64_t i = 0; i < n; ++i) {
    // Keep the grid's reach near the expected spacing so queries stay local; the rare
    // candidate farther than that from every point falls back to a scan.
    double want = 1.5 * max_packing_distance(std::max<int64_t>(i, 1), dim);
    if (want < 0.7 * grid.reach()) {
      grid.reset(want, std::size_t(n));
      for (std::size_t j = 0; j < ps.size(); ++j) grid.insert(uint32_t(j), ps.coords.data() + j * dim);
    }
    double best_d2 = -1.0;
    const int64_t candidates = m * i + 1;
    for (int64_t c = 0; c < candidates; ++c) {
      for (int k = 0; k < dim; ++k) x[k] = rng.uniform();
      double d2 = i == 0 ? 0.0 : nearest_sq(x);
      if (d2 > best_d2) {
        best_d2 = d2;
        std::copy(x, x + dim, best);
      }
    }
    grid.insert(uint32_t(ps.size()), best);
    ps.coords.insert(ps.coords.end(), best, best + dim);
    ps.radius.push_back(i == 0 ? diameter : std::sqrt(best_d2));
  }
  return ps;
}

}  // namespace pdrt
