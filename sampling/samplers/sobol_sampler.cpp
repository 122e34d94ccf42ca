// `sobol`: Owen-scrambled Sobol points, the modern baseline of pbrt-v4 and Cycles. Every
// 2-D family uses the first two Sobol dimensions (a (0,2)-sequence: van der Corput and the
// x+1 polynomial, v_j = v_{j-1} ^ (v_{j-1} >> 1)) with its own nested uniform (Owen)
// scramble seeded per (pixel, family, bounce), like pbrt-v4's padded Sobol sampler. Owen
// scrambling keeps the net property, so every power-of-two prefix is stratified in all
// elementary intervals, and prefixes extend.
#include "sampling/core/rng.h"
#include "sampling/samplers/owen_sobol.h"
#include "sampling/samplers/sampler.h"

#include <algorithm>

namespace pdrt {
namespace {

class SobolSampler final : public Sampler {
 public:
  explicit SobolSampler(uint64_t seed) : Sampler(seed) {}
  std::string name() const override { return sampler_name(SamplerKind::Sobol); }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    const uint64_t s = stream(px, py, f, bounce);
    return unit_from_u32(sobol_0(uint32_t(IndexShuffle(s)(uint64_t(index))), s));
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    const uint64_t s = stream(px, py, f, bounce);
    const uint32_t j = uint32_t(IndexShuffle(s)(uint64_t(index)));
    return {unit_from_u32(sobol_0(j, s)), unit_from_u32(sobol_1(j, mix64(s)))};
  }
  // The window [first, want) alone: the index shuffle, the second dimension from its byte
  // tables and the two scrambles, each in a loop over the window that vectorises.
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    const uint64_t s = stream(px, py, f, bounce);
    const uint32_t first = std::min(out->first, out->want), n = out->want - first;
    thread_local std::vector<uint32_t> perm, axis;
    perm.resize(n);
    IndexShuffle(s).fill(first, out->want, perm.data());
    out->own.resize(std::size_t(n) * family_dim(f));
    if (family_dim(f) == 1) {
      owen_scramble_all(n, perm.data(), s, out->own.data());
    } else {
      axis.resize(2 * std::size_t(n));
      owen_scramble_all(n, perm.data(), s, axis.data());
      for (uint32_t i = 0; i < n; ++i) perm[i] = sobol_dim1_reversed(perm[i]);
      owen_scramble_all(n, perm.data(), mix64(s), axis.data() + n);
      for (uint32_t i = 0; i < n; ++i) out->own[2 * i] = axis[i], out->own[2 * i + 1] = axis[n + i];
    }
    fill_prepared(out, first, out->want, family_dim(f), nullptr);
  }
  int64_t samples_available(int, int) const override { return int64_t(1) << 32; }
  // A value asked alone walks its index shuffle and two scrambles; a prepared one is a copy: preparing
  // every stream, the deep ones too, costs less (BM_PathPattern, issue 33).
  bool prepare_computes(Family) const override { return false; }
};

}  // namespace

std::unique_ptr<Sampler> make_sobol_sampler(uint64_t seed) { return std::make_unique<SobolSampler>(seed); }

}  // namespace pdrt
