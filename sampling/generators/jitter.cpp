// `jitter`: Cook 1986 §4 jittered grid in n-D. One uniform point per cell of the finest
// k^dim grid with k^dim <= count, cells visited in scanline order (x0 fastest).
#include "sampling/generators/generator.h"
#include "sampling/core/rng.h"

#include <cmath>
#include <cstdio>

namespace pdrt {

namespace {
int64_t jitter_cells_per_axis(int64_t count, int dim) {
  int64_t k = 1;
  auto fits = [&](int64_t kk) {
    double total = 1.0;
    for (int d = 0; d < dim; ++d) total *= double(kk);
    return total <= double(count);
  };
  while (fits(k + 1)) ++k;
  return k;
}

}  // namespace

PointSet generate_jitter(const GeneratorParams& p) {
  PointSet ps;
  ps.dim = p.dim;
  const int64_t k = jitter_cells_per_axis(*p.count, p.dim);
  int64_t total = 1;
  for (int d = 0; d < p.dim; ++d) total *= k;
  if (total != *p.count && !p.quiet)
    std::fprintf(stderr, "pdrt sample: jitter uses a %lld^%d grid: %lld points, not %lld\n", (long long)k, p.dim,
                 (long long)total, (long long)*p.count);
  Rng rng(p.seed, 0x6a6974);
  ps.coords.resize(std::size_t(total) * p.dim);
  const double cell = 1.0 / double(k);
  for (int64_t i = 0; i < total; ++i) {
    int64_t rest = i;
    for (int d = 0; d < p.dim; ++d) {
      int64_t c = rest % k;
      rest /= k;
      double x = (double(c) + rng.uniform()) * cell;
      ps.coords[std::size_t(i) * p.dim + d] = x < 1.0 ? x : std::nextafter(1.0, 0.0);
    }
  }
  return ps;
}

}  // namespace pdrt
