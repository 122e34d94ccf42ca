#pragma once
// 32-bit fixed point, the precision of every stored table and sample value: x in [0, 1) as
// floor(x 2^32), clamped to [0, 2^32 - 1].
#include <cmath>
#include <cstdint>

namespace pdrt {

inline uint32_t to_fixed(double x) {
  const double v = std::floor(x * 4294967296.0);
  return v <= 0 ? 0u : v >= 4294967295.0 ? 4294967295u : uint32_t(v);
}

// The top `bits` bits (0..32) of a fixed-point coordinate: its dyadic interval of width 2^-bits.
constexpr uint32_t fixed_top_bits(uint32_t v, int bits) { return bits ? v >> (32 - bits) : 0u; }

}  // namespace pdrt
