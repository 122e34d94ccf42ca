// The progressive jitter sampler (`jitter` in scenes and on the command line): Cook 1986
// §4.2 and §5.1 stratified sampling with prefix extension. Each (pixel, family, bounce)
// draws its own progressive jittered sequence (Christensen, Kensler & Kilpatrick 2018, "pj"): 2-D points are exactly k
// x k stratified whenever n = 4^j (1-D: n strata when n = 2^j), so n = k^2 samples are Cook's jittered grid, and
// because every family has an independent random stratum order the dimensions are decorrelated like Cook's per-pixel
// prototype permutations (Fig. 8).
//
// pj as a pure function of the index: point j >= 4^k (k maximal) is a child of point
// i = j mod 4^k. Between 4^k and 4^(k+1) each cell of the 2^k grid splits into four; group
// g = j / 4^k = 1 takes the sub-cell diagonally opposite its parent's, groups 2 and 3 take
// the other two in a random order; the point is uniform in its sub-cell. Values are 32-bit
// fixed point (cell index in the top bits, uniform bits below) from 32-bit hashes, so that
// prepare() builds a whole level of the sequence in a loop that vectorises.
#include "sampling/core/rng.h"
#include "sampling/samplers/sampler.h"

#include <bit>

namespace pdrt {
namespace {

// Wellons' lowbias32: a 32-bit integer hash (bijective) with low bias, two multiplies.
inline uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  return x ^ (x >> 16);
}

// The stream's keys: the uniform bits of each axis and the stratum-order choices.
struct Keys {
  uint32_t x, y, swap;
  explicit Keys(uint64_t stream) : x(uint32_t(stream)), y(uint32_t(stream >> 32)), swap(uint32_t(mix64(stream))) {}
};

constexpr uint32_t kGolden = 0x9e3779b9u;

// Cell c of a 2^bits grid with the uniform bits u below it.
inline uint32_t in_cell(uint32_t c, int bits, uint32_t u) { return (c << (32 - bits)) | (u >> bits); }

// Axis a (key ka) of point j >= 1 at level k (4^k <= j < 4^(k+1)) from its parent's value on that
// axis: group g = 1 flips both axes' sub-cell, groups 2 and 3 one each, in an order chosen
// per parent and level.
inline uint32_t child_2d(uint32_t j, int k, uint32_t parent, bool axis_y, uint32_t ka, const Keys& key) {
  const uint32_t g = j >> (2 * k), i = j & ((uint32_t(1) << (2 * k)) - 1);
  const uint32_t swap = hash32((i * kGolden) ^ (key.swap + uint32_t(k) * 0x85ebca6bu)) & 1u;
  const uint32_t other = (g == 2) ^ swap;  // 1: the x axis' sub-cell flips
  const uint32_t flip = (g == 1) | (axis_y ? other ^ 1u : other);
  const int bits = k + 1;
  return in_cell((parent >> (32 - bits)) ^ flip, bits, hash32((j * kGolden) ^ ka));
}

// Axis value of point j of the 1-D sequence from its parent j - 2^k (2^k <= j < 2^(k+1)):
// the half of the parent's cell at the 2^(k+1) grid that the parent does not occupy.
inline uint32_t child_1d(uint32_t j, int k, uint32_t parent, uint32_t ka) {
  const int bits = k + 1;
  return in_cell((parent >> (32 - bits)) ^ 1u, bits, hash32((j * kGolden) ^ ka));
}

// Point j as a pure function: its chain of parents from the root.
void pj_2d(uint32_t j, const Keys& key, uint32_t* x, uint32_t* y) {
  if (j == 0) {
    *x = hash32(key.x), *y = hash32(key.y);
    return;
  }
  const int k = (31 - __builtin_clz(j)) / 2;
  uint32_t px, py;
  pj_2d(j & ((uint32_t(1) << (2 * k)) - 1), key, &px, &py);
  *x = child_2d(j, k, px, false, key.x, key), *y = child_2d(j, k, py, true, key.y, key);
}

uint32_t pj_1d(uint32_t j, const Keys& key) {
  if (j == 0) return hash32(key.x);
  const int k = 31 - __builtin_clz(j);
  return child_1d(j, k, pj_1d(j - (uint32_t(1) << k), key), key.x);
}

// Level k of the sequence (points [4^k, min(4^(k+1), end)) in 2-D, [2^k, min(2^(k+1), end)) in
// 1-D), every parent already in x / y.
// (The parents are read through other pointers than the level is written through, so the
// compiler knows the two do not overlap.)
__attribute__((target_clones("avx2", "default"))) void level_2d(int k, uint32_t end, const Keys& key,
                                                                const uint32_t* __restrict px,
                                                                const uint32_t* __restrict py, uint32_t* __restrict ox,
                                                                uint32_t* __restrict oy) {
  const uint32_t base = uint32_t(1) << (2 * k), mask = base - 1;
  const Keys kk = key;
  for (uint32_t j = base; j < end; ++j) {
    ox[j - base] = child_2d(j, k, px[j & mask], false, kk.x, kk);
    oy[j - base] = child_2d(j, k, py[j & mask], true, kk.y, kk);
  }
}

__attribute__((target_clones("avx2", "default"))) void level_1d(int k, uint32_t end, const Keys& key,
                                                                const uint32_t* __restrict parent,
                                                                uint32_t* __restrict out) {
  const uint32_t base = uint32_t(1) << k, ka = key.x;
  for (uint32_t j = base; j < end; ++j) out[j - base] = child_1d(j, k, parent[j - base], ka);
}

class ProgressiveJitterSampler final : public Sampler {
 public:
  explicit ProgressiveJitterSampler(uint64_t seed) : Sampler(seed) {}
  std::string name() const override { return sampler_name(SamplerKind::Jitter); }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    if (family_dim(f) == 2) return get_2d(px, py, index, f, bounce)[0];
    const uint64_t s = stream(px, py, f, bounce);
    return unit_from_u32(pj_1d(uint32_t(IndexShuffle(s)(uint64_t(index))), Keys(s)));
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    const uint64_t s = stream(px, py, f, bounce);
    uint32_t x, y;
    pj_2d(uint32_t(IndexShuffle(s)(uint64_t(index))), Keys(s), &x, &y);
    return {unit_from_u32(x), unit_from_u32(y)};
  }

  // The sequence level by level up to the next power of two past `want` (every parent comes
  // before its children), then the window [first, want) read through the index shuffle.
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    const uint64_t s = stream(px, py, f, bounce);
    const Keys key(s);
    const uint32_t n = out->want;
    const uint32_t all = std::bit_ceil(n);  // the points' index range (0 and 1 give 1)
    const uint32_t first = std::min(out->first, n);
    thread_local std::vector<uint32_t> x, y, perm;
    perm.resize(n - first);
    IndexShuffle(s).fill(first, n, perm.data());
    x.resize(all);
    x[0] = hash32(key.x);
    if (family_dim(f) == 2) {
      y.resize(all);
      y[0] = hash32(key.y);
      for (int k = 0; (uint32_t(1) << (2 * k)) < all; ++k)
        level_2d(k, uint32_t(std::min<uint64_t>(uint64_t(1) << (2 * k + 2), all)), key, x.data(), y.data(),
                 x.data() + (std::size_t(1) << (2 * k)), y.data() + (std::size_t(1) << (2 * k)));
      fill_prepared(out, first, n, 2,
                    [&](uint32_t i, uint32_t* v) { v[0] = x[perm[i - first]], v[1] = y[perm[i - first]]; });
    } else {
      for (int k = 0; (uint32_t(1) << k) < all; ++k)
        level_1d(k, std::min(uint32_t(2) << k, all), key, x.data(), x.data() + (std::size_t(1) << k));
      fill_prepared(out, first, n, 1, [&](uint32_t i, uint32_t* v) { v[0] = x[perm[i - first]]; });
    }
  }
  // A value asked alone walks its chain of parents; a prepared one is a copy: preparing
  // every stream, the deep ones too, costs less (BM_PathPattern, issue 33).
  bool prepare_computes(Family) const override { return false; }
};

}  // namespace

std::unique_ptr<Sampler> make_progressive_jitter_sampler(uint64_t seed) {
  return std::make_unique<ProgressiveJitterSampler>(seed);
}

}  // namespace pdrt
