// The progressive jitter sampler (`jitter` in scenes and on the command line): Cook 1986
// §4.2 and §5.1 stratified sampling with prefix extension. Each (pixel, family, bounce)
// draws its own progressive jittered sequence (Christensen, Kensler & Kilpatrick 2018, "pj"): 2-D points are exactly k x k stratified whenever n = 4^j
// (1-D: n strata when n = 2^j), so n = k^2 samples are Cook's jittered grid, and because
// every family has an independent random stratum order the dimensions are decorrelated
// like Cook's per-pixel prototype permutations (Fig. 8).
//
// pj as a pure function of the index: point j >= 4^k (k maximal) is a child of point
// i = j mod 4^k. Between 4^k and 4^(k+1) each cell of the 2^k grid splits into four; group
// g = j / 4^k = 1 takes the sub-cell diagonally opposite its parent's, groups 2 and 3 take
// the other two in a random order; the point is uniform in its sub-cell.
#include "sampling/core/rng.h"
#include "sampling/samplers/sampler.h"

namespace pdrt {
namespace {

Vec2 pj_2d(uint64_t j, uint64_t stream) {
  uint64_t h = hash_combine(stream, j);
  if (j == 0) return {unit_from_u64(h), unit_from_u64(mix64(h))};
  int k = (63 - __builtin_clzll(j)) / 2;  // 4^k <= j < 4^(k+1)
  uint64_t n = uint64_t(1) << (2 * k), g = j >> (2 * k), i = j & (n - 1);
  Vec2 parent = pj_2d(i, stream);
  double cells = double(uint64_t(1) << (k + 1));
  int64_t cx = int64_t(parent[0] * cells), cy = int64_t(parent[1] * cells);
  int64_t sx = cx & 1, sy = cy & 1;
  bool swap = hash_combine(stream ^ 0x5ca1ab1eull, (i << 6) | uint64_t(k)) & 1;
  if (g == 1) sx ^= 1, sy ^= 1;
  else if ((g == 2) != swap) sx ^= 1;
  else sy ^= 1;
  cx = (cx & ~int64_t(1)) | sx;
  cy = (cy & ~int64_t(1)) | sy;
  return {(double(cx) + unit_from_u64(h)) / cells, (double(cy) + unit_from_u64(mix64(h))) / cells};
}

// 1-D: point j >= 2^k takes the half of its parent's cell (at the 2^(k+1) grid) that the
// parent does not occupy.
double pj_1d(uint64_t j, uint64_t stream) {
  uint64_t h = hash_combine(stream, j);
  if (j == 0) return unit_from_u64(h);
  int k = 63 - __builtin_clzll(j);
  uint64_t i = j - (uint64_t(1) << k);
  double cells = double(uint64_t(1) << (k + 1));
  int64_t c = int64_t(pj_1d(i, stream) * cells) ^ 1;
  return (double(c) + unit_from_u64(h)) / cells;
}

class ProgressiveJitterSampler final : public Sampler {
 public:
  explicit ProgressiveJitterSampler(uint64_t seed) : Sampler(seed) {}
  std::string name() const override { return "jitter"; }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t s = stream(px, py, f, bounce);
    return pj_1d(shuffle_index(uint64_t(index), s), s);
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    uint64_t s = stream(px, py, f, bounce);
    return pj_2d(shuffle_index(uint64_t(index), s), s);
  }
};

}  // namespace

std::unique_ptr<Sampler> make_progressive_jitter_sampler(uint64_t seed) {
  return std::make_unique<ProgressiveJitterSampler>(seed);
}

}  // namespace pdrt
