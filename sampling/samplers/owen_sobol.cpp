#include "sampling/samplers/owen_sobol.h"

namespace pdrt {

__attribute__((target_clones("avx2", "default"))) void owen_scramble_all(uint32_t n, const uint32_t* x, uint64_t seed,
                                                                         uint32_t* out) {
  for (uint32_t i = 0; i < n; ++i) out[i] = owen_scramble_reversed(x[i], seed);
}

}  // namespace pdrt
