// `zsobol` (zsobol_sampler.h). A pixel's samples beyond its block (adaptive refinement) take
// the same pixel's block in a fresh arrangement: block b of the pixel uses the dimension key
// hashed with b, so every block is a net and the order and scramble of each are independent.
#include "sampling/samplers/zsobol_sampler.h"

#include "sampling/core/errors.h"
#include "sampling/core/rng.h"
#include "sampling/samplers/nested_digits.h"
#include "sampling/samplers/owen_sobol.h"

#include <algorithm>
#include <array>
#include <bit>
#include <string>
#include <vector>

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

// The scramble key of a dimension's block of samples (block b: a pixel's samples [b 2^m, (b + 1) 2^m)).
uint64_t block_key(uint64_t dimension_stream, uint64_t block) {
  return mix64(dimension_stream ^ (block * 0x9e3779b97f4a7c15ull));
}

// Which of the 24 permutations the base-4 digit at `shift` takes: a hash of the unpermuted
// digits above it, so aligned blocks of indices map onto aligned blocks (Ahmed & Wonka §4).
uint32_t digit_permutation(uint32_t z, int shift, uint64_t key) {
  const uint64_t above = uint64_t(z) >> (shift + 2);
  const uint64_t h = mix64(key ^ (above * 0xc2b2ae3d27d4eb4full) ^ uint64_t(shift));
  return uint32_t(((h >> 32) * 24u) >> 32);
}

// An odd bit count's last bit, flipped by the bits above it.
uint32_t last_bit(uint32_t z, uint64_t key) {
  const uint64_t h = mix64(key ^ (uint64_t(z >> 1) * 0xc2b2ae3d27d4eb4full) ^ 0x5bd1e995ull);
  return (z & 1u) ^ uint32_t(h >> 63);
}

// zsobol_sobol_index for one key over indices in increasing order. The digits above the
// highest bit that changed from the previous index keep their output, and a digit's
// permutation is hashed once per distinct prefix above it (the digit at 2l from the bottom
// changes prefix every 4^(l+1) indices): a block of 4^j samples hashes about 4^j / 3 times
// instead of j 4^j, and the pixel's digits once.
class DigitCache {
 public:
  explicit DigitCache(int bits) : bits_(bits), levels_(bits / 2) {}
  void reset(uint64_t key) { key_ = key, above_.fill(UINT64_MAX), last_above_ = UINT64_MAX, have_ = false; }
  void reset(int bits, uint64_t key) { bits_ = bits, levels_ = bits / 2, reset(key); }
  uint32_t operator()(uint32_t z) {
    const int lo = bits_ & 1;
    int level = 0;
    uint32_t out = 0;
    if (have_) {
      const uint32_t diff = z ^ prev_;
      const int d = diff ? 31 - __builtin_clz(diff) : -1;
      level = bits_ - 2 > d ? std::min(levels_, (bits_ - 2 - d + 1) / 2) : 0;  // digits with shift > d
      out = level > 0 ? acc_[level - 1] : 0;
    }
    for (int shift = bits_ - 2 - 2 * level; shift >= lo; shift -= 2, ++level) {
      const uint64_t above = uint64_t(z) >> (shift + 2);
      if (above != above_[level]) above_[level] = above, perm_[level] = uint8_t(digit_permutation(z, shift, key_));
      out |= uint32_t(kPermutations4[perm_[level]][(z >> shift) & 3u]) << shift;
      acc_[level] = out;
    }
    prev_ = z, have_ = true;
    if (bits_ & 1) {
      if ((z >> 1) != last_above_) last_above_ = z >> 1, last_flip_ = last_bit(z & ~1u, key_);
      out |= (z & 1u) ^ last_flip_;
    }
    return out;
  }

 private:
  int bits_, levels_;
  uint64_t key_ = 0, last_above_ = UINT64_MAX;
  uint32_t last_flip_ = 0, prev_ = 0;
  bool have_ = false;
  std::array<uint64_t, 16> above_{};
  std::array<uint32_t, 16> acc_{};  // the output of the digits down to each level
  std::array<uint8_t, 16> perm_{};
};

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
  // sobol_index's values, each block's indices in order through a DigitCache (the pixel's
  // digits hashed once per block, the sample's once per distinct prefix), then each block's
  // scramble in a loop that vectorises.
  // The window [first, want) alone (a progressive render's later passes), block by block.
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    const int bits = 2 * k_ + m_, dim = family_dim(f);
    const uint32_t mask = k_ == 0 ? 0u : (uint32_t(1) << k_) - 1, end = out->want;
    const uint32_t first = std::min(out->first, end), n = end - first;
    const uint32_t pixel = bits == 0 ? 0 : uint32_t(uint64_t(morton2(uint32_t(px) & mask, uint32_t(py) & mask)) << m_);
    const uint64_t block_size = uint64_t(1) << m_, stream0 = sample_stream_from_hash(seed_hash_, 0, 0, f, bounce);
    thread_local std::vector<uint32_t> index, axis;
    index.resize(std::size_t(n) * dim), axis.resize(std::size_t(n) * dim);
    uint32_t* d1 = index.data() + n;  // the second dimension's unscrambled values
    for (uint64_t b0 = first & ~(block_size - 1); b0 < end; b0 += block_size) {
      // Indices [lo, hi) of the block starting at b0, stored from at = lo - first on.
      const uint64_t lo = std::max<uint64_t>(b0, first), hi = std::min<uint64_t>(b0 + block_size, end);
      const uint32_t count = uint32_t(hi - lo), at = uint32_t(lo - first);
      const uint64_t key = block_key(stream0, b0 >> m_);
      const uint32_t top = digit_cache(key)(pixel | uint32_t(lo - b0)) & ~uint32_t(block_size - 1);
      block_indices(top, pixel, uint32_t(lo - b0), uint32_t(hi - b0), key, index.data() + at);
      owen_scramble_all(count, index.data() + at, key, axis.data() + at);
      if (dim == 1) continue;
      // The second dimension is linear over GF(2) in the index bits: the pixel's part (the same
      // through a block) once, the sample's m bits per value.
      const uint32_t high = sobol_dim1_reversed(uint32_t(index[at] & ~(block_size - 1)));
      for (uint32_t i = 0; i < count; ++i)
        d1[at + i] = high ^ sobol_dim1_reversed(uint32_t(index[at + i] & (block_size - 1)));
      owen_scramble_all(count, d1 + at, mix64(key), axis.data() + n + at);
    }
    fill_prepared(out, first, end, dim, [&](uint32_t i, uint32_t* v) {
      v[0] = axis[i - first];
      if (dim == 2) v[1] = axis[n + i - first];
    });
  }

  // A value asked alone hashes every digit of the pixel's Morton index; prepared, a few
  // hashes per block: preparing every stream, the deep ones too, costs less (BM_PathPattern).
  bool prepare_computes(Family) const override { return false; }

 private:
  // zsobol_sobol_index(pixel | i, 2k + m, key) for a <= i < e (indices in the pixel's block of
  // 2^m), into out[i - a]: `top` is its pixel digits (the thread's DigitCache gives them), the
  // sample's are nested_digits' walk with each level's last permutation and the last pair's flip
  // kept. The same hashes, so the same values.
  void block_indices(uint32_t top, uint32_t pixel, uint32_t a, uint32_t e, uint64_t key, uint32_t* out) const {
    std::array<uint32_t, 16> level_node;
    std::array<uint8_t, 16> level_perm{};
    level_node.fill(UINT32_MAX);
    const auto perm = [&](int l, uint32_t node) -> const std::array<uint8_t, 4>& {
      const int shift = m_ - 2 - 2 * l;
      if (level_node[std::size_t(l)] != node)
        level_node[std::size_t(l)] = node,
        level_perm[std::size_t(l)] =
            uint8_t(digit_permutation(pixel | uint32_t(uint64_t(node) << (shift + 2)), shift, key));
      return kPermutations4[level_perm[std::size_t(l)]];
    };
    uint32_t pair = UINT32_MAX, flip = 0;
    const auto tail = [&](uint32_t i) {  // the last bit of an odd count, one hash per pair
      if (i >> 1 != pair) pair = i >> 1, flip = last_bit(pixel | (i & ~1u), key);
      return (i & 1u) ^ (flip & 1u);
    };
    nested_digits(m_, top, a, e, perm, tail, out);
  }

  // The Sobol index of a sample and the key of its block's scramble.
  uint32_t sobol_index(int px, int py, int64_t index, Family f, int bounce, uint64_t* key) const {
    const uint32_t mask = k_ == 0 ? 0u : (uint32_t(1) << k_) - 1;  // pixels outside the image wrap
    const uint64_t block = uint64_t(index) >> m_;
    *key = block_key(sample_stream_from_hash(seed_hash_, 0, 0, f, bounce), block);
    const uint32_t low = uint32_t(uint64_t(index) & ((uint64_t(1) << m_) - 1));
    const uint32_t z = m_ + 2 * k_ == 0 ? 0 : (morton2(uint32_t(px) & mask, uint32_t(py) & mask) << m_) | low;
    return digit_cache(*key)(z);
  }
  // The thread's DigitCache of a block key. Consecutive pixels share their Morton index's upper
  // digits, so a cache kept per key from pixel to pixel rehashes only the digits below the
  // highest bit that changed (a pixel's value alone hashed all 2k + m of them). 256 caches by
  // the key's top bits (a path's few dozen keys rarely share one); a cache serves one key of
  // one sampler at a time.
  DigitCache& digit_cache(uint64_t key) const {
    struct Memo {
      uint64_t sampler = 0, key = 0;
      DigitCache cache{0};
    };
    thread_local std::array<Memo, 256> memos;
    Memo& m = memos[key >> 56];
    if (m.sampler != instance_ || m.key != key) m.sampler = instance_, m.key = key, m.cache.reset(2 * k_ + m_, key);
    return m.cache;
  }
  int m_ = 0;  // log2 of the block of samples a pixel takes
  int k_ = 0;  // bits per pixel coordinate
};

}  // namespace

uint32_t zsobol_sobol_index(uint32_t z, int bits, uint64_t key) {
  uint32_t out = 0;
  for (int shift = bits - 2; shift >= (bits & 1); shift -= 2)
    out |= uint32_t(kPermutations4[digit_permutation(z, shift, key)][(z >> shift) & 3u]) << shift;
  return out | ((bits & 1) ? last_bit(z, key) : 0);
}

std::unique_ptr<Sampler> make_zsobol_sampler(uint64_t seed, const SamplerShape& shape) {
  return std::make_unique<ZSobolSampler>(seed, shape);
}

}  // namespace pdrt
