// `random`: independent uniform values (white noise), the baseline. Each value hashes its
// full coordinates, so it is replayable in any order; 32-bit fixed point, like every sampler.
#include "sampling/core/rng.h"
#include "sampling/samplers/sampler.h"

namespace pdrt {
namespace {

// One hash per value (the stream hash is already well mixed).
uint64_t value_bits(uint64_t stream, uint64_t index) { return mix64(stream ^ (index * 0x9e3779b97f4a7c15ull)); }

class RandomSampler final : public Sampler {
 public:
  explicit RandomSampler(uint64_t seed) : Sampler(seed) {}
  std::string name() const override { return sampler_name(SamplerKind::Random); }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    return unit_from_u32(uint32_t(value_bits(stream(px, py, f, bounce), uint64_t(index)) >> 32));
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    const uint64_t h = value_bits(stream(px, py, f, bounce), uint64_t(index));
    return {unit_from_u32(uint32_t(h >> 32)), unit_from_u32(uint32_t(h))};
  }
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    const uint64_t s = stream(px, py, f, bounce);
    fill_prepared(out, out->first, out->want, family_dim(f), [&](uint32_t i, uint32_t* v) {
      const uint64_t h = value_bits(s, i);
      v[0] = uint32_t(h >> 32);
      if (family_dim(f) == 2) v[1] = uint32_t(h);
    });
  }
};

}  // namespace

std::unique_ptr<Sampler> make_random_sampler(uint64_t seed) { return std::make_unique<RandomSampler>(seed); }

}  // namespace pdrt
