// `random`: independent uniform values (white noise), the baseline. Each value hashes its
// full coordinates, so it is replayable in any order.
#include "sampling/core/rng.h"
#include "sampling/samplers/sampler.h"

namespace pdrt {
namespace {

class RandomSampler final : public Sampler {
 public:
  explicit RandomSampler(uint64_t seed) : Sampler(seed) {}
  std::string name() const override { return "random"; }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    return unit_from_u64(hash_combine(stream(px, py, f, bounce), uint64_t(index)));
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t h = hash_combine(stream(px, py, f, bounce), uint64_t(index));
    return {unit_from_u64(h), unit_from_u64(mix64(h))};
  }
};

}  // namespace

std::unique_ptr<Sampler> make_random_sampler(uint64_t seed) { return std::make_unique<RandomSampler>(seed); }

}  // namespace pdrt
