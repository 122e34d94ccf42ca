#pragma once
// FNV-1a, 64-bit (Fowler, Noll & Vo): a stable byte hash for file checksums and cache keys,
// the same on every platform and standard library.
#include <cstdint>
#include <string_view>

namespace pdrt {

inline constexpr uint64_t kFnv1aOffsetBasis = 0xcbf29ce484222325ull;

constexpr uint64_t fnv1a(std::string_view bytes, uint64_t h = kFnv1aOffsetBasis) {
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

}  // namespace pdrt
