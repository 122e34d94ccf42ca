// `sobol`: Owen-scrambled Sobol points, the modern baseline of pbrt-v4 and Cycles. Every
// 2-D family uses the first two Sobol dimensions (a (0,2)-sequence: van der Corput and the
// x+1 polynomial, v_j = v_{j-1} ^ (v_{j-1} >> 1)) with its own nested uniform (Owen)
// scramble seeded per (pixel, family, bounce), like pbrt-v4's padded Sobol sampler. Owen
// scrambling keeps the net property, so every power-of-two prefix is stratified in all
// elementary intervals, and prefixes extend.
#include "sampling/core/rng.h"
#include "sampling/samplers/sampler.h"

namespace pdrt {
namespace {

uint32_t sobol_dim0(uint32_t i) {  // van der Corput: the bits of i mirrored
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  return ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
}

uint32_t sobol_dim1(uint32_t i) {
  uint32_t v = 1u << 31, x = 0;
  for (; i; i >>= 1, v ^= v >> 1)
    if (i & 1) x ^= v;
  return x;
}

uint32_t reverse_bits(uint32_t i) { return sobol_dim0(i); }

// Hash-based Owen scramble (Burley 2020, after Laine & Karras 2011): in bit-reversed order,
// adding a seed and xoring with products by even constants only lets a bit depend on the
// bits below it, i.e. on the bits above it in the original order, which is exactly the
// structure of a nested (Owen) scramble; four rounds make the flips look independent.
// Two multiplies per round instead of one hash per bit.
uint32_t owen_scramble(uint32_t x, uint64_t seed) {
  x = reverse_bits(x);
  x += uint32_t(seed ^ (seed >> 32));
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverse_bits(x);
}

class SobolSampler final : public Sampler {
 public:
  explicit SobolSampler(uint64_t seed) : Sampler(seed) {}
  std::string name() const override { return "sobol"; }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t s = stream(px, py, f, bounce);
    index = int64_t(shuffle_index(uint64_t(index), s));
    return unit_from_u32(owen_scramble(sobol_dim0(uint32_t(index)), s));
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t s = stream(px, py, f, bounce);
    index = int64_t(shuffle_index(uint64_t(index), s));
    return {unit_from_u32(owen_scramble(sobol_dim0(uint32_t(index)), s)),
            unit_from_u32(owen_scramble(sobol_dim1(uint32_t(index)), mix64(s)))};
  }
  int64_t samples_available(int, int) const override { return int64_t(1) << 32; }
};

}  // namespace

std::unique_ptr<Sampler> make_sobol_sampler(uint64_t seed) { return std::make_unique<SobolSampler>(seed); }

}  // namespace pdrt
