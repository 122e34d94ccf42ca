// `sobol`: Owen-scrambled Sobol points, the modern baseline of pbrt-v4 and Cycles. Every
// 2-D family uses the first two Sobol dimensions (a (0,2)-sequence: van der Corput and the
// x+1 polynomial, v_j = v_{j-1} ^ (v_{j-1} >> 1)) with its own nested uniform (Owen)
// scramble seeded per (pixel, family, bounce), like pbrt-v4's padded Sobol sampler. Owen
// scrambling keeps the net property, so every power-of-two prefix is stratified in all
// elementary intervals, and prefixes extend.
#include "rng.h"
#include "sampler.h"

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

// Nested uniform scramble: bit b (from the top) flips by a hash of the bits above it, so
// every elementary interval's sub-intervals are permuted independently (Owen 1995).
uint32_t owen_scramble(uint32_t x, uint64_t seed) {
  uint32_t out = 0;
  for (int b = 31; b >= 8; --b) {  // 24 bits: the precision of a float's mantissa
    uint32_t prefix = b == 31 ? 0u : (x >> (b + 1));
    uint64_t h = mix64(seed ^ (uint64_t(prefix) << 6) ^ uint64_t(31 - b));
    out |= (((x >> b) & 1u) ^ uint32_t(h & 1u)) << b;
  }
  // Below float precision: random low bits so values are not on a 2^-24 lattice.
  out |= uint32_t(mix64(seed ^ x) & 0xffu);
  return out;
}

double to_unit(uint32_t bits) { return double(bits) * 0x1.0p-32; }

class SobolSampler final : public Sampler {
 public:
  explicit SobolSampler(uint64_t seed) : Sampler(seed) {}
  std::string name() const override { return "sobol"; }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t s = stream(px, py, f, bounce);
    return to_unit(owen_scramble(sobol_dim0(uint32_t(index)), s));
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t s = stream(px, py, f, bounce);
    return {to_unit(owen_scramble(sobol_dim0(uint32_t(index)), s)),
            to_unit(owen_scramble(sobol_dim1(uint32_t(index)), mix64(s)))};
  }
  int64_t samples_available(int, int) const override { return int64_t(1) << 32; }
};

}  // namespace

std::unique_ptr<Sampler> make_sobol_sampler(uint64_t seed) { return std::make_unique<SobolSampler>(seed); }

}  // namespace pdrt
