// `lloyd`: McCool & Fiume §6 Lloyd relaxation (the generalised Lloyd algorithm). Starts from
// a McCool–Fiume Poisson-disk set of exactly `count` points and moves every point to the
// centroid of its Voronoi cell, estimated by Monte Carlo as in the paper, `iterations` times.
// On the torus when periodic (McCool optimises on a toroid), inside the unit cube otherwise.
#include "sampling/generators/generator.h"
#include "sampling/generators/detail/neighbor_grid.h"
#include "sampling/core/rng.h"

#include <cmath>
#include <limits>
#include <vector>

namespace pdrt {
namespace {

// Index of the nearest site to q: grid first, exhaustive scan when the grid's reach is short.
uint32_t nearest_site(const NeighborGrid& grid, const PointSet& sites, const double* q) {
  double best = std::numeric_limits<double>::infinity();
  uint32_t arg = 0;
  grid.visit_near(q, [&](uint32_t id, const double*, double d2) {
    if (d2 < best) best = d2, arg = id;
    return false;
  });
  if (best <= grid.reach() * grid.reach()) return arg;
  for (std::size_t i = 0; i < sites.size(); ++i) {
    double d2 = distance_sq(q, sites.coords.data() + i * sites.dim, sites.dim, sites.periodic);
    if (d2 < best) best = d2, arg = uint32_t(i);
  }
  return arg;
}

}  // namespace

PointSet generate_lloyd(const GeneratorParams& p) {
  GeneratorParams start = p;
  start.method = "mccool";
  start.attempts.reset();
  PointSet ps = generate_mccool(start);
  ps.dim = p.dim;
  ps.periodic = p.periodic;
  ps.radius.clear();  // points move: there is no placement radius any more
  const int dim = p.dim;
  const std::size_t n = ps.size();
  // Monte Carlo probes per site and iteration (McCool estimated centroids this way).
  const int64_t probes_per_site = p.attempts.value_or(64);
  const double reach = 1.5 * max_packing_distance(int64_t(n), dim);
  Rng rng(p.seed, 0x6c6c6f79);
  std::vector<double> sum(n * dim);
  std::vector<uint32_t> hits(n);
  double q[kMaxDim];
  for (int it = 0; it < p.lloyd_iterations; ++it) {
    NeighborGrid grid(dim, p.periodic, reach, n);
    for (std::size_t i = 0; i < n; ++i) grid.insert(uint32_t(i), ps.coords.data() + i * dim);
    std::fill(sum.begin(), sum.end(), 0.0);
    std::fill(hits.begin(), hits.end(), 0u);
    const int64_t probes = probes_per_site * int64_t(n);
    for (int64_t s = 0; s < probes; ++s) {
      for (int k = 0; k < dim; ++k) q[k] = rng.uniform();
      uint32_t site = nearest_site(grid, ps, q);
      const double* c = ps.coords.data() + std::size_t(site) * dim;
      // Accumulate offsets from the site so a cell that wraps the torus averages correctly.
      for (int k = 0; k < dim; ++k) sum[std::size_t(site) * dim + k] += axis_delta(q[k], c[k], p.periodic);
      ++hits[site];
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!hits[i]) continue;
      for (int k = 0; k < dim; ++k) {
        double v = ps.coords[i * dim + k] + sum[i * dim + k] / double(hits[i]);
        if (p.periodic) v -= std::floor(v);
        v = std::clamp(v, 0.0, std::nextafter(1.0, 0.0));
        ps.coords[i * dim + k] = v;
      }
    }
  }
  return ps;
}

}  // namespace pdrt
