#pragma once
// Bit reversal, the form in which nested (Owen) scrambles are hashed (Laine & Karras 2011).
#include <cstdint>

namespace pdrt {

inline uint32_t reverse_bits32(uint32_t x) {
  x = __builtin_bswap32(x);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);
  x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
  return ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
}

inline uint64_t reverse_bits64(uint64_t x) {
  return uint64_t(reverse_bits32(uint32_t(x))) << 32 | reverse_bits32(uint32_t(x >> 32));
}

}  // namespace pdrt
