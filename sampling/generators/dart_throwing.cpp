// `dart`: naive dart throwing (Cook 1986 §3, McCool §3.2) at a fixed minimum distance.
// Stops after `attempts` consecutive rejected darts, or when `count` points are placed.
#include "sampling/generators/generator.h"
#include "sampling/generators/detail/neighbor_grid.h"
#include "sampling/core/rng.h"

#include <cstdio>
#include <limits>

namespace pdrt {

PointSet generate_dart(const GeneratorParams& p) {
  const int dim = p.dim;
  const double r = p.radius ? *p.radius : radius_for_count(*p.count, dim, p.periodic);
  const int64_t limit = p.count ? *p.count : std::numeric_limits<int64_t>::max();
  const int64_t budget = p.attempts.value_or(1000);
  const double r2 = r * r;
  double expected = p.count ? double(*p.count) : expected_count_for_radius(r, dim);
  NeighborGrid grid(dim, p.periodic, r, std::size_t(expected));
  Rng rng(p.seed, 0x64617274);
  PointSet ps;
  ps.dim = dim;
  double x[kMaxDim];
  int64_t failures = 0;
  while (int64_t(ps.size()) < limit && failures < budget) {
    for (int k = 0; k < dim; ++k) x[k] = rng.uniform();
    if (grid.any_closer(x, r2)) {
      ++failures;
      continue;
    }
    failures = 0;
    grid.insert(uint32_t(ps.size()), x);
    ps.coords.insert(ps.coords.end(), x, x + dim);
    ps.radius.push_back(r);
  }
  if (!p.quiet)
    std::fprintf(stderr, "pdrt sample: dart placed %zu points at radius %.6g (%s)\n", ps.size(), r,
                 int64_t(ps.size()) >= limit ? "count reached" : "attempt budget exhausted");
  return ps;
}

}  // namespace pdrt
