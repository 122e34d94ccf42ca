// `zsobol` (zsobol_sampler.h). A pixel's samples beyond its block (adaptive refinement) take
// the same pixel's block in a fresh arrangement: block b of the pixel uses the dimension key
// hashed with b, so every block is a net and the order and scramble of each are independent.
#include "sampling/samplers/zsobol_sampler.h"

#include "sampling/core/errors.h"
#include "sampling/core/rng.h"
#include "sampling/samplers/owen_sobol.h"

#include <array>
#include <bit>
#include <string>

namespace pdrt {
namespace {

// The 24 permutations of {0, 1, 2, 3}, in lexicographic order.
constexpr std::array<std::array<uint8_t, 4>, 24> kPermutations4 = [] {
  std::array<std::array<uint8_t, 4>, 24> p{};
  std::array<uint8_t, 4> cur = {0, 1, 2, 3};
  for (auto& q : p) {
    q = cur;
    int i = 2;  // next lexicographic permutation
    while (i >= 0 && cur[i] > cur[i + 1]) --i;
    if (i < 0) break;
    int j = 3;
    while (cur[j] < cur[i]) --j;
    std::swap(cur[i], cur[j]);
    for (int a = i + 1, b = 3; a < b; ++a, --b) std::swap(cur[a], cur[b]);
  }
  return p;
}();

// Interleaves the low 16 bits of x and y (x in the even bits).
uint32_t morton2(uint32_t x, uint32_t y) {
  auto spread = [](uint32_t v) {
    v &= 0xffffu;
    v = (v | (v << 8)) & 0x00ff00ffu;
    v = (v | (v << 4)) & 0x0f0f0f0fu;
    v = (v | (v << 2)) & 0x33333333u;
    return (v | (v << 1)) & 0x55555555u;
  };
  return spread(x) | (spread(y) << 1);
}

int ceil_log2(int64_t n) { return n <= 1 ? 0 : 64 - __builtin_clzll(uint64_t(n - 1)); }

class ZSobolSampler final : public Sampler {
 public:
  ZSobolSampler(uint64_t seed, const SamplerShape& o) : Sampler(seed) {
    if (o.samples_per_pixel < 1) throw UsageError("sampler zsobol: samples per pixel must be >= 1");
    if (o.width < 1 || o.height < 1) throw UsageError("sampler zsobol: the image must have at least one pixel");
    m_ = ceil_log2(o.samples_per_pixel);
    k_ = ceil_log2(std::max(o.width, o.height));
    if (2 * k_ + m_ > 32)
      throw UsageError("sampler zsobol: " + std::to_string(o.width) + " x " + std::to_string(o.height) + " pixels at " +
                       std::to_string(o.samples_per_pixel) + " samples per pixel need " + std::to_string(2 * k_ + m_) +
                       " bits of Morton and sample index, at most 32 (fewer samples per pixel or a smaller image)");
  }
  std::string name() const override { return sampler_name(SamplerKind::ZSobol); }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t key;
    const uint32_t j = sobol_index(px, py, index, f, bounce, &key);
    return unit_from_u32(sobol_0(j, key));
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t key;
    const uint32_t j = sobol_index(px, py, index, f, bounce, &key);
    return {unit_from_u32(sobol_0(j, key)), unit_from_u32(sobol_1(j, mix64(key)))};
  }
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    fill_prepared(out, out->want, family_dim(f), [&](uint32_t i, uint32_t* v) {
      uint64_t key;
      const uint32_t j = sobol_index(px, py, i, f, bounce, &key);
      v[0] = sobol_0(j, key);
      if (family_dim(f) == 2) v[1] = sobol_1(j, mix64(key));
    });
  }

 private:
  // The Sobol index of a sample and the key of its block's scramble.
  uint32_t sobol_index(int px, int py, int64_t index, Family f, int bounce, uint64_t* key) const {
    const uint32_t mask = k_ == 0 ? 0u : (uint32_t(1) << k_) - 1;  // pixels outside the image wrap
    const uint64_t block = uint64_t(index) >> m_;
    *key = mix64(sample_stream_from_hash(seed_hash_, 0, 0, f, bounce) ^ (block * 0x9e3779b97f4a7c15ull));
    const uint32_t low = uint32_t(uint64_t(index) & ((uint64_t(1) << m_) - 1));
    const uint32_t z = m_ + 2 * k_ == 0 ? 0 : (morton2(uint32_t(px) & mask, uint32_t(py) & mask) << m_) | low;
    return zsobol_sobol_index(z, 2 * k_ + m_, *key);
  }
  int m_ = 0;  // log2 of the block of samples a pixel takes
  int k_ = 0;  // bits per pixel coordinate
};

}  // namespace

uint32_t zsobol_sobol_index(uint32_t z, int bits, uint64_t key) {
  // Base-4 digits from the most significant; each is permuted by a hash of the unpermuted
  // digits above it, so aligned blocks of indices map onto aligned blocks (Ahmed & Wonka §4).
  uint32_t out = 0;
  int shift = bits - 2;
  for (; shift >= 0; shift -= 2) {
    const uint64_t above = uint64_t(z) >> (shift + 2);
    const uint64_t h = mix64(key ^ (above * 0xc2b2ae3d27d4eb4full) ^ uint64_t(shift));
    const uint32_t digit = (z >> shift) & 3u;
    out |= uint32_t(kPermutations4[uint32_t(((h >> 32) * 24u) >> 32)][digit]) << shift;
  }
  if (shift == -1) {  // an odd bit count: the last bit is flipped by the bits above it
    const uint64_t h = mix64(key ^ (uint64_t(z >> 1) * 0xc2b2ae3d27d4eb4full) ^ 0x5bd1e995ull);
    out |= (z & 1u) ^ uint32_t(h >> 63);
  }
  return out;
}

std::unique_ptr<Sampler> make_zsobol_sampler(uint64_t seed, const SamplerShape& shape) {
  return std::make_unique<ZSobolSampler>(seed, shape);
}

}  // namespace pdrt
