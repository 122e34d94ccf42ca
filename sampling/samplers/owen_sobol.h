#pragma once
// The first two dimensions of the Sobol sequence (a (0,2)-sequence) under a hash-based nested
// uniform (Owen) scramble, shared by `sobol` and `zsobol`.
#include "sampling/core/bit_reverse.h"

#include <array>
#include <cstdint>

namespace pdrt {

// The second Sobol dimension (x+1 polynomial: v_j = v_{j-1} ^ (v_{j-1} >> 1)), computed bit
// reversed (v_0 = 1, v_j = v_{j-1} ^ (v_{j-1} << 1)), the form the scramble works on.
// Linear over GF(2) in the bits of i, so one table per byte of i: four reads and three xors
// instead of a step per bit.
inline constexpr std::array<std::array<uint32_t, 256>, 4> kSobolDim1Bytes = [] {
  std::array<std::array<uint32_t, 256>, 4> t{};
  for (int b = 0; b < 4; ++b)
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t j = i << (8 * b), v = 1, x = 0;
      for (; j; j >>= 1, v ^= v << 1)
        if (j & 1) x ^= v;
      t[b][i] = x;
    }
  return t;
}();
inline uint32_t sobol_dim1_reversed(uint32_t i) {
  return kSobolDim1Bytes[0][i & 255] ^ kSobolDim1Bytes[1][(i >> 8) & 255] ^ kSobolDim1Bytes[2][(i >> 16) & 255] ^
         kSobolDim1Bytes[3][i >> 24];
}

// Hash-based Owen scramble (Burley 2020, after Laine & Karras 2011, with Vegdahl's improved
// rounds as in pbrt-v4's FastOwenScrambler) of a value given bit reversed: adding a seed and
// multiplying (by even constants, or by an odd factor) only lets a bit depend on the bits
// below it, i.e. on the bits above it in the original order, which is exactly the structure
// of a nested (Owen) scramble. A few multiplies instead of one hash per bit. The first
// dimension (van der Corput) is the index reversed, so its reversed form is the index itself.
inline uint32_t owen_scramble_reversed(uint32_t x, uint64_t seed) {
  const uint32_t s = uint32_t(seed ^ (seed >> 32));
  x ^= x * 0x3d20adeau;
  x += s;
  x *= (s >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return reverse_bits32(x);
}

// out[i] = owen_scramble_reversed(x[i], seed) for i < n, in a loop that vectorises (AVX2 where
// the processor has it): the prepared streams' values.
void owen_scramble_all(uint32_t n, const uint32_t* x, uint64_t seed, uint32_t* out);

// Scrambled Sobol dimensions 0 and 1 of index j, in 32-bit fixed point.
inline uint32_t sobol_0(uint32_t j, uint64_t s) { return owen_scramble_reversed(j, s); }
inline uint32_t sobol_1(uint32_t j, uint64_t s) { return owen_scramble_reversed(sobol_dim1_reversed(j), s); }

}  // namespace pdrt
