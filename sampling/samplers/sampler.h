#pragma once
// The replayable per-pixel sampler (pbrt-v4 style): every value is a pure function of
// (pixel, sample index, dimension family, bounce, seed), so images do not depend on thread
// count or tile order, and raising a pixel from n to m samples only appends samples.
#include "sampling/core/derived_seeds.h"
#include "sampling/samplers/sampler_names.h"
#include "sampling/samplers/sampler_profile.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace pdrt {

// The sampled dimensions of distribution ray tracing (Cook 1986 §5).
enum class Family : uint8_t { Pixel = 0, Lens = 1, Time = 2, Light = 3, Gloss = 4 };
inline constexpr int kFamilyCount = 5;
inline constexpr int family_dim(Family f) { return f == Family::Time ? 1 : 2; }
const char* family_name(Family f);

using Vec2 = std::array<double, 2>;

// Sample values live in [0, 1): the largest double below 1, and the clamp into [0, 1) that
// keeps values computed in floating point (offsets, flips) inside it.
inline constexpr double kBelowOne = 0x1.fffffffffffffp-1;
constexpr double clamp_to_unit(double x) { return x < 0.0 ? 0.0 : x < 1.0 ? x : kBelowOne; }

// Hash of a sample's coordinates: the per-(pixel, family, bounce) stream every sampler uses,
// in two steps so samplers mix their seed once (sample_hash_seed, sampling/core/derived_seeds.h).
uint64_t sample_stream_from_hash(uint64_t seed_hash, int px, int py, Family family, int bounce);

// A per-stream permutation of sample indices that maps every prefix [0, 2^k) onto itself:
// bit c of the index flips by a hash of the bits above it, except while those are all zero.
// Sequences that are stratified by index (progressive jitter, Sobol) otherwise pair sample i of one
// family with sample i of another through a fixed map, so a pixel's estimate converges to
// the integral along that map instead of over the product domain (a per-pixel bias that
// more samples never remove). Power-of-two prefixes keep their point sets, so their
// stratification and prefix extension are unchanged.
// O(1) per index: the bits below the leading one are a nested (Owen) scramble of themselves,
// computed as in Laine & Karras 2011 / Burley 2020 on their reversal (an add, products by
// even constants and one by an odd factor let a bit depend only on the bits below it;
// Vegdahl's rounds), keyed by the stream and the leading bit's position.
class IndexShuffle {
 public:
  explicit IndexShuffle(uint64_t stream) : key_(stream ^ 0x9c8d7e6f5a4b3c2dull) {}
  uint64_t operator()(uint64_t index) const;
  // out[i - first] = (*this)(i) for first <= i < n, a power of two at a time in a loop that
  // vectorises.
  void fill(uint32_t first, uint32_t n, uint32_t* out) const;

 private:
  uint64_t key_;
  mutable int top_ = -1;       // the last leading-bit position and its scramble seed: a loop over
  mutable uint64_t seed_ = 0;  // indices hashes once per power of two
};
inline uint64_t shuffle_index(uint64_t index, uint64_t stream) { return IndexShuffle(stream)(index); }

// What a sampler can precompute for one (pixel, family, bounce) stream, so that a value is
// one table read and an affine map (pbrt-v4 does such per-pixel work in StartPixelSample).
// Axis k of value i (base <= i < count):
// off[k] + mul[k] * uint32((coords[((i - base) << shift) + src[k]] ^ xr[k]) + add[k])
// (the xor is a digital shift, which keeps elementary intervals; the unsigned add is a
// toroidal shift in 32-bit fixed point), clamped to [0, 1).
// The numeric fields are left uninitialised on purpose: PixelSampleState keeps 320 of them
// per thread and fills one only when its stream is first used. `own` holds the coordinates
// when the sampler has to assemble them per pixel (coords then points into it).
// What value() reads fills the first 64 bytes, one cache line (the struct is aligned to it):
// between two sample values the path tracer's own work evicts much of L1.
struct alignas(64) PreparedStream {
  const uint32_t* coords;  // null: nothing prepared, ask the sampler
  uint32_t base = 0;       // indices from base on are stored ...
  uint8_t shift;           // log2 of the values per point
  uint8_t src[2];
  uint32_t xr[2], add[2];
  double off[2], mul[2];
  uint32_t count;  // ... below count (a sampler that computes values prepares a window)
  // Input: the caller needs indices [first, want) now. A sampler may prepare fewer above
  // (count < want) and more below (base < first): one that computes its values prepares the
  // window [first, want) alone, since a progressive render's later passes and the deep
  // bounces few paths reach would otherwise recompute or waste the indices below.
  uint32_t first = 0, want;
  bool grows;  // preparing again with a larger `want` gives more values
  std::vector<uint32_t> own;

  double value(int64_t index, int k) const { return stored(std::size_t(index - base), k); }
  // Axis k of the r-th stored value, i.e. of index base + r.
  double stored(std::size_t r, int k) const {
    const uint32_t c = (coords[(r << shift) + src[k]] ^ xr[k]) + add[k];
    return clamp_to_unit(off[k] + mul[k] * double(c));
  }
};
static_assert(offsetof(PreparedStream, count) == 64, "value()'s fields fill one cache line");

// A PreparedStream holding the computed values of indices [first, n) per axis (dim 1 or 2) in
// 32-bit fixed point: value(i, k) = v_k(i) / 2^32, where value(i, v) writes v_0 (and v_1) of
// index i. With `value` null, own already holds the (n - first) * dim values.
template <class ValueFn>
void fill_prepared(PreparedStream* out, uint32_t first, uint32_t n, int dim, ValueFn&& value) {
  first = std::min(first, n);
  if constexpr (!std::is_same_v<std::decay_t<ValueFn>, std::nullptr_t>) {
    out->own.resize(std::size_t(n - first) * dim);
    for (uint32_t i = first; i < n; ++i) value(i, out->own.data() + std::size_t(i - first) * dim);
  }
  out->coords = out->own.data();
  out->base = first;
  out->count = n;
  out->shift = dim == 2 ? 1 : 0;
  out->grows = true;
  for (int k = 0; k < 2; ++k)
    out->src[k] = uint8_t(dim == 2 ? k : 0), out->xr[k] = 0, out->add[k] = 0, out->off[k] = 0.0,
    out->mul[k] = 0x1.0p-32;
}

class Sampler {
 public:
  virtual ~Sampler() = default;
  virtual std::string name() const = 0;
  uint64_t seed() const { return seed_; }

  // Value of sample `index` of pixel (px, py) in `family` at path vertex `bounce`.
  // Pixel-family values are offsets within the pixel, in [0,1)^2. get_1d of a 2-D family is
  // get_2d's first axis.
  virtual double get_1d(int px, int py, int64_t index, Family family, int bounce) const = 0;
  virtual Vec2 get_2d(int px, int py, int64_t index, Family family, int bounce) const = 0;

  // Fills `out` so that out->value(i, k) equals get_2d(px, py, i, family, bounce)[k] (or
  // get_1d for k = 0) bit for bit for every i in [out->base, out->count), with base <=
  // out->first and, when `grows` is set, count >= out->want; sets out->coords = nullptr when
  // the sampler has no such form (the default). Every built-in sampler has one: a value then
  // costs a table read.
  virtual void prepare(int px, int py, Family family, int bounce, PreparedStream* out) const;
  // True: preparing costs about what the values asked one by one would, so PixelSampleState
  // prepares only the streams most samples use and asks for deep ones value by value; false
  // (a sampler whose values cost far more alone than prepared): every stream is prepared.
  virtual bool prepare_computes(Family) const { return true; }

  // How many samples pixel (px, py) can take before values stop being well distributed
  // (prefix extension is exact below this); unlimited samplers return INT64_MAX.
  virtual int64_t samples_available(int px, int py) const;

  // Samples pixel (px, py) takes in a render of `spp` samples per pixel: its indices are
  // [0, samples_in_pixel(spp)), and a pass from spp a to b takes [samples_in_pixel(a),
  // samples_in_pixel(b)). spp for every sampler but those whose pixels share one image-plane
  // pattern (`poisson-ip`, image_plane_sampler.h), where the count varies about spp.
  virtual int64_t samples_in_pixel(int, int, int64_t spp) const { return spp; }
  // True for those: their pixels' estimates divide by the expected filter weight, not the sum.
  virtual bool pixel_counts_vary() const { return false; }

 protected:
  explicit Sampler(uint64_t seed) : seed_(seed), seed_hash_(sample_hash_seed(seed)), instance_(next_instance()) {}
  // The hash of (pixel, family, bounce) every value of that stream derives from.
  uint64_t stream(int px, int py, Family family, int bounce) const {
    return sample_stream_from_hash(seed_hash_, px, py, family, bounce);
  }
  uint64_t seed_;
  uint64_t seed_hash_;  // mixed once here, not per sample
  // Distinct for every sampler made in the process: the key of a sampler's per-thread caches
  // (a cache of one must not serve another that happens to reuse its address).
  uint64_t instance_;

 private:
  static uint64_t next_instance();
};

// The sampler state of the pixel sample being traced (pbrt-v4's StartPixelSample + Get1D/
// Get2D on top of the pure functions): one per thread, reused across pixels. A stream of the
// current pixel is prepared on first use for the rest of the pass, so the values of the pass's
// later samples cost a table read (values are identical to the Sampler's).
class PixelSampleState {
 public:
  explicit PixelSampleState(const Sampler& s) : s_(&s) {}
  const Sampler& sampler() const { return *s_; }
  void start_pixel_sample(int px, int py, int64_t index) {
    if (px != px_ || py != py_) {
      px_ = px, py_ = py, ++epoch_;
      for (uint32_t i = 0; i < touched_; ++i) held_[touched_slot_[i]].span = 0;
      touched_ = 0;
    }
    index_ = index;
  }
  // The next start_pixel_sample starts a pixel afresh, whatever pixel it names (a state kept
  // from one tile to the next, renderer/render/thread_sampler_states.h).
  void forget_pixel() { px_ = py_ = INT32_MIN; }
  // The current pass takes indices [begin, end) of the pixel's streams: a stream that enough
  // of its samples use is prepared from the index that first asks to `end` at once (without a
  // pass: 16 values, doubling).
  void set_pixel_pass(int64_t begin, int64_t end) {
    begin_ = std::max<int64_t>(0, begin);
    budget_ = uint32_t(std::clamp<int64_t>(end, 1, kMaxBudget));
  }
  double get_1d(Family f, int bounce = 0) const {
    SamplerScope scope;
    const int k = int(f) * kSlots + bounce;
    if (unsigned(bounce) < unsigned(kSlots)) {
      const uint64_t r = uint64_t(index_) - held_[k].lo;  // the stored value's rank
      if (r < held_[k].span) return slot_[k].stored(r, 0);
    }
    return get_1d_slow(f, bounce);
  }
  Vec2 get_2d(Family f, int bounce = 0) const {
    SamplerScope scope;
    const int k = int(f) * kSlots + bounce;
    if (unsigned(bounce) < unsigned(kSlots)) {
      const uint64_t r = uint64_t(index_) - held_[k].lo;
      if (r < held_[k].span) return {slot_[k].stored(r, 0), slot_[k].stored(r, 1)};
    }
    return get_2d_slow(f, bounce);
  }

  // A hash of (seed, pixel, sample index, bounce) for a decision that needs an unbounded number
  // of random numbers (a layered BSDF's random walks, renderer/render/bxdf/layered.h): it seeds
  // a generator local to the call, so every value stays a pure function of the sample.
  uint64_t walk_key(int bounce) const {
    uint64_t h = hash_combine(walk_key_seed(s_->seed()), (uint64_t(uint32_t(px_)) << 32) | uint32_t(py_));
    return hash_combine(hash_combine(h, uint64_t(index_)), uint64_t(uint32_t(bounce)));
  }

  // Bounce salts cached per family (renderer/render/sample_dimensions.h ties path depth to it).
  static constexpr int kCachedSalts = 64;

 private:
  static constexpr int kSlots = kCachedSalts;
  // A value outside the held windows: prepared() or the sampler's own (out of line, so that
  // the common call above saves no registers).
  [[gnu::noinline]] double get_1d_slow(Family f, int bounce) const {
    const PreparedStream* p = prepared(f, bounce);
    if (p) return p->value(index_, 0);
    return s_->get_1d(px_, py_, index_, f, bounce);
  }
  [[gnu::noinline]] Vec2 get_2d_slow(Family f, int bounce) const {
    const PreparedStream* p = prepared(f, bounce);
    if (p) return {p->value(index_, 0), p->value(index_, 1)};
    return s_->get_2d(px_, py_, index_, f, bounce);
  }
  // The stream's prepared values when they hold the current index (preparing them if worth
  // it), else null: the caller asks the sampler for the value alone.
  const PreparedStream* prepared(Family f, int bounce) const {
    if (unsigned(bounce) >= unsigned(kSlots) || index_ < 0 || index_ >= INT32_MAX) return nullptr;
    const int k = int(f) * kSlots + bounce;
    PreparedStream& p = slot_[k];
    Book& b = book_[k];
    if (b.epoch != epoch_) b.epoch = epoch_, b.uses = 0, p.coords = nullptr;
    if (b.uses == kDeclined) return nullptr;
    ++b.uses;
    const auto holds = [&] { return p.coords && uint64_t(index_) >= p.base && uint64_t(index_) < p.count; };
    if (!holds()) {
      if (p.coords && !p.grows) return nullptr;  // all the sampler stores; past it, values alone
      // The pass's last sample reads each stream once: preparing it would only add the
      // bookkeeping (at 1 spp, every value).
      if (index_ + 1 == budget_) return nullptr;
      // A sampler that computes the values it prepares gains only on a stream that at least
      // half of the pass's samples so far have used (the camera's and the first bounces'); the
      // deep bounces that few paths reach are asked value by value. The others prepare the
      // window from this index to the pass's end.
      if (s_->prepare_computes(f) && 2 * int64_t(b.uses) < index_ - begin_ + 1) return nullptr;
      int64_t end = std::max<int64_t>(budget_, index_ + 1);
      if (p.coords && index_ >= budget_) end = index_ + 2 * int64_t(p.want - p.first);  // no pass: doubling
      p.first = uint32_t(index_), p.want = uint32_t(std::min<int64_t>(end, INT32_MAX));
      s_->prepare(px_, py_, f, bounce, &p);
      if (!p.coords && b.uses == 1) b.uses = kDeclined;
      if (!holds()) {
        held_[k] = {0, 0};
        return nullptr;
      }
    }
    if (b.listed != epoch_) b.listed = epoch_, touched_slot_[touched_++] = uint16_t(k);
    held_[k] = {p.base, p.count - p.base};  // the pixel's later calls in it take the fast path
    return &p;
  }
  static constexpr uint32_t kDeclined = UINT32_MAX;        // the sampler has no prepared form
  static constexpr int64_t kMaxBudget = int64_t(1) << 16;  // larger passes grow by doubling
  const Sampler* s_;
  int px_ = INT32_MIN, py_ = INT32_MIN;
  uint32_t budget_ = 16;
  int64_t begin_ = 0;
  int64_t index_ = 0;
  uint32_t epoch_ = 1;  // differs from the slots' initial 0 even before the first pixel
  // Per slot, in one 12-byte record (one cache line where three arrays took three): the pixel
  // (epoch) its uses count, the uses this pass, the epoch in which it was listed in touched_slot_.
  struct Book {
    uint32_t epoch, uses, listed;
  };
  mutable std::array<Book, kFamilyCount * kSlots> book_{};
  // The slots prepared for this pixel: values of indices in [lo, lo + span) are stored (span
  // 0: ask prepared()), in one small array so that the common call reads one 8-byte word
  // before its value; touched_slot_ lists the nonzero spans, cleared when the pixel changes
  // (Book::listed: a slot is listed once per pixel).
  struct Held {
    uint32_t lo, span;
  };
  mutable std::array<Held, kFamilyCount * kSlots> held_{};
  mutable std::array<uint16_t, kFamilyCount * kSlots> touched_slot_{};
  mutable uint32_t touched_ = 0;
  mutable PreparedStream slot_[kFamilyCount * kSlots];
};

// The Monte Carlo samplers that render under every setting (every kind but `regular` and
// `poisson-ip`, which renders only by splatting): unbiased over seeds, the ones every sampler
// test covers; `compare` defaults to compare_default_sampler_names() of them.
const std::vector<std::string>& sampler_names();
// Every name `make_sampler` accepts: sampler_names(), `poisson-ip` and `regular`.
const std::vector<std::string>& all_sampler_names();
std::string sampler_name_list();  // "random, jitter, ..., regular"

// What a sampler that arranges samples across pixels (zsobol, poisson-ss, poisson-ip) needs of the
// render: the samples per pixel of its first pass (the block each pixel takes; poisson-ip's
// period) and the film's size.
struct SamplerShape {
  int64_t samples_per_pixel = 16;
  int width = 1024, height = 1024;
};

// Throws UsageError naming the sampler for an unknown name (and for a shape zsobol or poisson-ss cannot order).
std::unique_ptr<Sampler> make_sampler(const std::string& name, uint64_t seed, const SamplerShape& shape = {});
std::unique_ptr<Sampler> make_sampler(SamplerKind kind, uint64_t seed, const SamplerShape& shape = {});
}  // namespace pdrt
