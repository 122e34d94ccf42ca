// `regular`: Cook's regular-sampling baseline (Cook 1986 §2-3), not a Monte Carlo sampler. Every
// pixel, bounce and seed gets the same deterministic points: the unscrambled 2-D Sobol' (0,2)-
// sequence (van der Corput and the Pascal-matrix dimension), shifted by 1/2 so that sample 0 is
// the pixel centre, and every power-of-four prefix a regular lattice. A pattern repeated in
// every pixel aliases a signal above the pixel rate into moiré, which the stochastic samplers
// turn into noise: the checker-horizon demonstration. Its estimates are biased (the same over
// seeds), so it is kept out of sampler_names() and the Monte Carlo tests.
#include "sampling/core/rng.h"
#include "sampling/samplers/sampler.h"

#include <vector>

namespace pdrt {
namespace {

uint32_t van_der_corput(uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
  return i;
}

// Sobol's second dimension: column j of its generator matrix is row j of Pascal's triangle
// mod 2, read from the most significant bit (v_j = 1/2, 3/4, 5/8, 15/16, ...).
uint32_t sobol_second(uint32_t i) {
  uint32_t v = 1u << 31, x = 0;
  for (; i; i >>= 1, v ^= v >> 1)
    if (i & 1) x ^= v;
  return x;
}

class RegularSampler final : public Sampler {
 public:
  explicit RegularSampler(uint64_t seed) : Sampler(seed) {}
  std::string name() const override { return sampler_name(SamplerKind::Regular); }
  double get_1d(int, int, int64_t index, Family, int) const override {
    return unit_from_u32(van_der_corput(uint32_t(index)) + 0x80000000u);
  }
  Vec2 get_2d(int, int, int64_t index, Family, int) const override {
    return {unit_from_u32(van_der_corput(uint32_t(index)) + 0x80000000u),
            unit_from_u32(sobol_second(uint32_t(index)) + 0x80000000u)};
  }
  // Every stream is the same sequence: its first kStored points, computed once, are a table
  // every stream reads (a 1-D family reads the first axis).
  void prepare(int, int, Family, int, PreparedStream* out) const override {
    static const std::vector<uint32_t> points = [] {
      std::vector<uint32_t> p(2 * std::size_t(kStored));
      for (uint32_t i = 0; i < kStored; ++i)
        p[2 * i] = van_der_corput(i) + 0x80000000u, p[2 * i + 1] = sobol_second(i) + 0x80000000u;
      return p;
    }();
    fill_prepared(out, 0, kStored, 2, nullptr);
    out->coords = points.data();
    out->grows = false;
  }
  bool prepare_computes(Family) const override { return false; }

 private:
  static constexpr uint32_t kStored = uint32_t(1) << 16;
};

}  // namespace

std::unique_ptr<Sampler> make_regular_sampler(uint64_t seed) { return std::make_unique<RegularSampler>(seed); }

}  // namespace pdrt
