// Sampler registry and the shared stream hash.
#include "sampling/samplers/sampler.h"

#include "sampling/core/bit_reverse.h"
#include "sampling/core/errors.h"
#include "sampling/samplers/image_plane_sampler.h"
#include "sampling/samplers/poisson_sampler.h"
#include "sampling/samplers/screen_poisson_sampler.h"
#include "sampling/samplers/zsobol_sampler.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <atomic>
#include <limits>

namespace pdrt {

std::unique_ptr<Sampler> make_random_sampler(uint64_t seed);
std::unique_ptr<Sampler> make_regular_sampler(uint64_t seed);
std::unique_ptr<Sampler> make_progressive_jitter_sampler(uint64_t seed);
std::unique_ptr<Sampler> make_sobol_sampler(uint64_t seed);
std::unique_ptr<Sampler> make_pmj02bn_sampler(uint64_t seed);

const char* family_name(Family f) {
  switch (f) {
    case Family::Pixel:
      return "pixel";
    case Family::Lens:
      return "lens";
    case Family::Time:
      return "time";
    case Family::Light:
      return "light";
    default:
      return "gloss";
  }
}

void Sampler::prepare(int, int, Family, int, PreparedStream* out) const { out->coords = nullptr; }

int64_t Sampler::samples_available(int, int) const { return std::numeric_limits<int64_t>::max(); }

const std::vector<std::string>& sampler_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const NamedValue<SamplerKind>& s : kSamplerNames)
      if (s.value != SamplerKind::Regular && !samples_image_plane(s.value)) n.push_back(s.name);
    return n;
  }();
  return names;
}

const std::vector<std::string>& all_sampler_names() {
  static const std::vector<std::string> names = names_in(kSamplerNames);
  return names;
}

std::string sampler_name_list() { return name_list(kSamplerNames); }

std::unique_ptr<Sampler> make_sampler(SamplerKind kind, uint64_t seed, const SamplerShape& shape) {
  switch (kind) {
    case SamplerKind::Random:
      return make_random_sampler(seed);
    case SamplerKind::Regular:
      return make_regular_sampler(seed);
    case SamplerKind::Jitter:
      return make_progressive_jitter_sampler(seed);
    case SamplerKind::Sobol:
      return make_sobol_sampler(seed);
    case SamplerKind::Pmj02bn:
      return make_pmj02bn_sampler(seed);
    case SamplerKind::ZSobol:
      return make_zsobol_sampler(seed, shape);
    case SamplerKind::Poisson:
      return make_poisson_sampler(seed, default_tables());
    case SamplerKind::Poisson065:
      return make_poisson_sampler(seed, default_tables(TableSetKind::Poisson065));
    case SamplerKind::PoissonSS:
      return make_screen_poisson_sampler(seed, default_tables(), shape);
    case SamplerKind::PoissonBN: {
      PoissonOptions o;
      o.screen_keys_spp = std::max<int64_t>(1, shape.samples_per_pixel);
      return make_poisson_sampler(seed, default_tables(), o);
    }
    case SamplerKind::PoissonIP:
      return make_image_plane_sampler(make_poisson_sampler(seed, default_tables()), shape, sampler_name(kind));
  }
  return nullptr;
}

std::unique_ptr<Sampler> make_sampler(const std::string& name, uint64_t seed, const SamplerShape& shape) {
  SamplerKind kind{};
  if (!parse_sampler(name, &kind))
    throw UsageError("sampler: unknown sampler '" + name + "' (known: " + sampler_name_list() + ")");
  return make_sampler(kind, seed, shape);
}

uint64_t Sampler::next_instance() {
  static std::atomic<uint64_t> next{1};
  return next++;
}

uint64_t sample_stream_from_hash(uint64_t seed_hash, int px, int py, Family family, int bounce) {
  // One finaliser over odd-constant multiples of the coordinates: distinct inputs differ in
  // the low bits of at least one product, and mix64 spreads that over all 64 bits.
  uint64_t k = uint64_t(uint32_t(px)) * 0x9e3779b97f4a7c15ull ^ uint64_t(uint32_t(py)) * 0xc2b2ae3d27d4eb4full ^
               (uint64_t(uint8_t(family)) << 56) ^ (uint64_t(uint32_t(bounce)) << 40);
  return mix64(seed_hash ^ k);
}

namespace {

// Index 2^top + low, 1 <= top < 32: the `top` bits of `low` reversed (most significant at bit
// 0), where an add and products by even constants let a bit depend only on the bits below
// it, i.e. on the index bits above its own; then reversed back.
// The rounds are Vegdahl's improved Laine–Karras hash (as in pbrt-v4's FastOwenScrambler):
// the multiply by an odd seed-dependent factor makes the flips of neighbouring bits independent.
inline uint32_t shuffle32(uint32_t low, int top, uint32_t seed) {
  uint32_t x = reverse_bits32(low << (32 - top));
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return (uint32_t(1) << top) | (reverse_bits32(x) >> (32 - top));
}

// out[low - from] for from <= low < to.
__attribute__((target_clones("avx2", "default"))) void shuffle_block(uint32_t from, uint32_t to, int top, uint32_t seed,
                                                                     uint32_t* out) {
  for (uint32_t low = from; low < to; ++low) out[low - from] = shuffle32(low, top, seed);
}

}  // namespace

uint64_t IndexShuffle::operator()(uint64_t index) const {
  if (index < 2) return index;
  const int top = 63 - __builtin_clzll(index);  // the leading bit never flips
  if (top != top_) top_ = top, seed_ = mix64(key_ + uint64_t(top));
  if (top < 32) return shuffle32(uint32_t(index) & ((uint32_t(1) << top) - 1), top, uint32_t(seed_));
  uint64_t x = reverse_bits64(index << (64 - top));  // the same rounds in 64 bits
  x ^= x * 0x3d20adea6c50b47cull;
  x += seed_;
  x *= (seed_ >> 32) | 1u;
  x ^= x * 0x05526c56b82f1e52ull;
  x ^= x * 0x53a22864c7afe638ull;
  return (uint64_t(1) << top) | (reverse_bits64(x) >> (64 - top));
}

void IndexShuffle::fill(uint32_t first, uint32_t n, uint32_t* out) const {
  for (uint32_t i = first; i < std::min<uint32_t>(n, 2); ++i) out[i - first] = i;
  for (int top = 1; top < 32 && (uint32_t(1) << top) < n; ++top) {
    // The block of indices [2^top, 2^(top+1)) that the window [first, n) overlaps.
    const uint32_t base = uint32_t(1) << top, end = uint32_t(std::min<uint64_t>(uint64_t(base) * 2, n));
    if (end <= first) continue;
    const uint32_t from = std::max(first, base), seed = uint32_t(mix64(key_ + uint64_t(top)));
    if (end - from <= 2) {  // one or two indices: no call through the clone's resolver
      for (uint32_t i = from; i < end; ++i) out[i - first] = shuffle32(i - base, top, seed);
    } else {
      shuffle_block(from - base, end - base, top, seed, out + (from - first));
    }
  }
}

}  // namespace pdrt
