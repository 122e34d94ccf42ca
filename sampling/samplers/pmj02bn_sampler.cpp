// `pmj02bn`: Christensen et al.'s progressive multi-jittered (0,2) sequences with blue-noise
// selection (sampling/generators/pmj02bn.h) as a replayable sampler (docs/sampling.md). A pool of
// kSequences sequences of kLength points is generated in process, each on first use, and
// cached. Every (pixel, family, bounce) stream takes a sequence by hash, a symmetry of the square
// (the axis swap) and a digital (xor) shift, and reads it through its own IndexShuffle: the
// shift and the swap map every elementary interval onto one and the shuffle keeps every prefix
// [0, 2^k) as a set, so every power-of-two prefix of a 2-D stream stays a (0,m,2)-net (of a
// time stream, which reads one axis, stratified) and every value is uniform over seeds.
// Indices past kLength continue in another sequence, shift and shuffle per round of kLength.
#include "sampling/core/rng.h"
#include "sampling/generators/pmj02bn.h"
#include "sampling/samplers/sampler.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <mutex>
#include <vector>

namespace pdrt {
namespace {

constexpr uint32_t kSequences = 16;
constexpr uint32_t kLength = 4096;
constexpr uint64_t kShiftSalt = 0x706d6a2d73686966ull, kShuffleSalt = 0x706d6a2d73687566ull;

// Sequence k of the pool (seed k + 1, the generator's default candidates), generated once.
const uint32_t* sequence(uint32_t k) {
  static std::array<std::once_flag, kSequences> once;
  static std::array<std::vector<uint32_t>, kSequences> pool;
  std::call_once(once[k], [k] { pool[k] = pmj02bn_fixed(kLength, k + 1); });
  return pool[k].data();
}

class Pmj02bnSampler final : public Sampler {
 public:
  // The pool is generated here, all sequences at once and in parallel (about 60 ms of CPU), not
  // on first use inside the render: set-up, like the table samplers' loading, not sampling work.
  explicit Pmj02bnSampler(uint64_t seed) : Sampler(seed) {
    tbb::parallel_for(uint32_t(0), kSequences, [](uint32_t k) { sequence(k); });
  }
  std::string name() const override { return sampler_name(SamplerKind::Pmj02bn); }

  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    PreparedStream p;
    const uint64_t h = round_hash(px, py, f, bounce, uint64_t(index) / kLength);
    map_stream(h, &p);
    const int64_t j = int64_t(IndexShuffle(h ^ kShuffleSalt)(uint64_t(index) % kLength));
    return {p.value(j, 0), p.value(j, 1)};
  }
  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    return get_2d(px, py, index, f, bounce)[0];
  }

  // Round 0 of the stream: the window's points of the sequence through the stream's index
  // shuffle, copied (two coordinates as one 8-byte word); the swap and the shift stay in the
  // map, so a value is the same double as get_2d's.
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    const uint64_t h = round_hash(px, py, f, bounce, 0);
    map_stream(h, out);
    const uint32_t* seq = out->coords;
    const uint32_t n = std::min(out->want, kLength), first = std::min(out->first, n);
    thread_local std::vector<uint32_t> perm;
    perm.resize(n - first);
    IndexShuffle(h ^ kShuffleSalt).fill(first, n, perm.data());
    out->own.resize(2 * std::size_t(n - first));
    for (uint32_t i = 0; i < n - first; ++i)
      std::memcpy(out->own.data() + 2 * std::size_t(i), seq + 2 * std::size_t(perm[i]), 8);
    out->coords = out->own.data();
    out->base = first;
    out->count = n;
    out->grows = n < kLength;
  }
  // A shuffled copy costs about as little as poisson's (a table read per value), so every
  // stream is prepared, the deep ones too.
  bool prepare_computes(Family) const override { return false; }

  int64_t samples_available(int, int) const override { return kLength; }

 private:
  uint64_t round_hash(int px, int py, Family f, int bounce, uint64_t round) const {
    const uint64_t h = stream(px, py, f, bounce);
    return round ? hash_combine(h, round) : h;
  }

  // The stream's sequence, axis swap and digital shift (a 1-D stream reads one axis).
  static void map_stream(uint64_t h, PreparedStream* out) {
    out->coords = sequence(uint32_t(((h >> 32) * kSequences) >> 32));
    out->base = 0;
    out->count = kLength;
    out->shift = 1;
    out->grows = false;
    const bool swap = h & 1;
    const uint64_t s = mix64(h ^ kShiftSalt);
    for (int k = 0; k < 2; ++k) {
      out->src[k] = uint8_t(swap ? 1 - k : k);
      out->xr[k] = uint32_t(s >> (32 * k)), out->add[k] = 0, out->off[k] = 0.0, out->mul[k] = 0x1.0p-32;
    }
  }
};

}  // namespace

std::unique_ptr<Sampler> make_pmj02bn_sampler(uint64_t seed) { return std::make_unique<Pmj02bnSampler>(seed); }

}  // namespace pdrt
