// Sampler registry and the shared stream hash.
#include "sampling/samplers/sampler.h"

#include "sampling/core/errors.h"
#include "sampling/samplers/poisson_sampler.h"
#include "sampling/core/rng.h"

#include <limits>

namespace pdrt {

std::unique_ptr<Sampler> make_random_sampler(uint64_t seed);
std::unique_ptr<Sampler> make_progressive_jitter_sampler(uint64_t seed);
std::unique_ptr<Sampler> make_sobol_sampler(uint64_t seed);

const char* family_name(Family f) {
  switch (f) {
    case Family::Pixel: return "pixel";
    case Family::Lens: return "lens";
    case Family::Time: return "time";
    case Family::Light: return "light";
    default: return "gloss";
  }
}

void Sampler::prepare(int, int, Family, int, PreparedStream* out) const { out->coords = nullptr; }

int64_t Sampler::samples_available(int, int) const { return std::numeric_limits<int64_t>::max(); }

const std::vector<std::string>& sampler_names() {
  static const std::vector<std::string> names = {"random", "jitter", "poisson", "sobol"};
  return names;
}

std::unique_ptr<Sampler> make_sampler(const std::string& name, uint64_t seed) {
  if (name == "random") return make_random_sampler(seed);
  if (name == "jitter") return make_progressive_jitter_sampler(seed);
  if (name == "sobol") return make_sobol_sampler(seed);
  if (name == "poisson") return make_poisson_sampler(seed, default_tables());
  std::string known;
  for (const auto& n : sampler_names()) {
    if (!known.empty()) known += ", ";
    known += n;
  }
  throw UsageError("sampler: unknown sampler '" + name + "' (known: " + known + ")");
}

uint64_t sample_seed_hash(uint64_t seed) { return mix64(seed ^ 0x70647274ull); }

uint64_t sample_stream_from_hash(uint64_t seed_hash, int px, int py, Family family, int bounce) {
  // One finaliser over odd-constant multiples of the coordinates: distinct inputs differ in
  // the low bits of at least one product, and mix64 spreads that over all 64 bits.
  uint64_t k = uint64_t(uint32_t(px)) * 0x9e3779b97f4a7c15ull ^ uint64_t(uint32_t(py)) * 0xc2b2ae3d27d4eb4full ^
               (uint64_t(uint8_t(family)) << 56) ^ (uint64_t(uint32_t(bounce)) << 40);
  return mix64(seed_hash ^ k);
}

uint64_t shuffle_index(uint64_t index, uint64_t stream) {
  if (index < 2) return index;
  const int top = 63 - __builtin_clzll(index);  // the leading bit never flips
  const uint64_t key = mix64(stream ^ 0x5f);      // decorrelated from the stream's other uses
  uint64_t out = index;
  for (int c = 0; c < top; ++c) {
    uint64_t above = index >> (c + 1);  // non-zero: contains the leading bit
    out ^= (mix64(key ^ (above * 0x9e3779b97f4a7c15ull) ^ uint64_t(c)) & 1u) << c;
  }
  return out;
}

}  // namespace pdrt
