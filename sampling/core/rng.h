#pragma once
// Deterministic random numbers: pcg-cpp engines and our own conversions, so the
// output is the same with every standard library (no std::*_distribution).
#include <pcg_random.hpp>

#include <cstdint>

namespace pdrt {

// SplitMix64 finaliser: decorrelates nearby seeds and hashes integer tuples.
constexpr uint64_t mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

constexpr uint64_t hash_combine(uint64_t a, uint64_t b) { return mix64(a ^ mix64(b)); }

// Uniform double in [0, 1) from the top 53 bits of a 64-bit hash or engine output (exact).
constexpr double unit_from_u64(uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

// [0, 1) from all 32 bits, read as fixed point (bits / 2^32, exact).
constexpr double unit_from_u32(uint32_t bits) { return double(bits) * 0x1.0p-32; }

class Rng {
 public:
  // `stream` selects an independent pcg sequence for the same seed.
  explicit Rng(uint64_t seed, uint64_t stream = 0) : engine_(mix64(seed), mix64(stream ^ 0x5851f42d4c957f2dull)) {}

  uint64_t next_u64() { return engine_(); }

  // Uniform double in [0, 1) with 53 random bits.
  double uniform() { return unit_from_u64(engine_()); }

  // Uniform double in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  // Uniform integer in [0, n), unbiased (Lemire's multiply-and-reject).
  uint64_t below(uint64_t n) {
    unsigned __int128 m = (unsigned __int128)engine_() * n;
    uint64_t low = uint64_t(m);
    if (low < n) {
      uint64_t threshold = (0 - n) % n;
      while (low < threshold) {
        m = (unsigned __int128)engine_() * n;
        low = uint64_t(m);
      }
    }
    return uint64_t(m >> 64);
  }

  // Standard normal deviate (Marsaglia polar method; deterministic across libraries).
  double normal();

 private:
  pcg64 engine_;
};

inline double Rng::normal() {
  for (;;) {
    double u = 2.0 * uniform() - 1.0, v = 2.0 * uniform() - 1.0;
    double s = u * u + v * v;
    if (s > 0.0 && s < 1.0) return u * __builtin_sqrt(-2.0 * __builtin_log(s) / s);
  }
}

}  // namespace pdrt
