// `random`: independent uniform points, the "Poisson" process of McCool §3.1 (baseline).
#include "sampling/generators/generator.h"
#include "sampling/core/rng.h"

namespace pdrt {

PointSet generate_random(const GeneratorParams& p) {
  PointSet ps;
  ps.dim = p.dim;
  Rng rng(p.seed, 0x72616e64);
  ps.coords.resize(std::size_t(*p.count) * p.dim);
  for (double& x : ps.coords) x = rng.uniform();
  return ps;
}

}  // namespace pdrt
