#include "renderer/render/mix_material.h"

#include "sampling/core/rng.h"

#include <cstring>

namespace pdrt {

float mix_hash(const Vec3& p, const Vec3& wo, int level) {
  uint64_t h = mix64(uint64_t(uint32_t(level)) + 0x6d69786d61746572ull);
  for (float f : {p.x, p.y, p.z, wo.x, wo.y, wo.z}) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    h = hash_combine(h, bits);
  }
  return float(h >> 40) * 0x1.0p-24f;  // 24 bits: exact in float, < 1
}

}  // namespace pdrt
