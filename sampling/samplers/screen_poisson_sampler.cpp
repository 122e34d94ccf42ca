// `poisson-ss` (screen_poisson_sampler.h).
#include "sampling/samplers/screen_poisson_sampler.h"

#include "sampling/core/errors.h"
#include "sampling/core/rng.h"
#include "sampling/samplers/nested_digits.h"
#include "sampling/samplers/progressive_order.h"

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <bit>
#include <string>
#include <vector>

namespace pdrt {
namespace {

// The 24 permutations of a base-4 digit, decoded from their Lehmer codes; permutation r sends
// digit d to (kDigitPermutations[r] >> 2d) & 3.
constexpr std::array<uint8_t, 24> kDigitPermutations = [] {
  std::array<uint8_t, 24> t{};
  for (int r = 0; r < 24; ++r) {
    std::array<int, 4> left = {0, 1, 2, 3};
    int code = r, count = 4;
    for (int d = 0; d < 4; ++d, --count) {
      const int c = code % count;
      code /= count;
      t[std::size_t(r)] = uint8_t(t[std::size_t(r)] | (left[std::size_t(c)] << (2 * d)));
      for (int i = c; i + 1 < count; ++i) left[std::size_t(i)] = left[std::size_t(i) + 1];
    }
  }
  return t;
}();

// Permutation r's images of digits 0..3.
constexpr std::array<std::array<uint32_t, 4>, 24> kSpreadPermutation = [] {
  std::array<std::array<uint32_t, 4>, 24> t{};
  for (std::size_t r = 0; r < 24; ++r)
    for (std::size_t d = 0; d < 4; ++d) t[r][d] = (uint32_t(kDigitPermutations[r]) >> (2 * d)) & 3u;
  return t;
}();

// The permutation of the digit of z at `shift`: a hash of key and of z's bits above the digit.
uint8_t digit_permutation(uint32_t z, int shift, uint64_t key) {
  const uint64_t h = mix64(key ^ ((uint64_t(z) >> (shift + 2)) * 0xc2b2ae3d27d4eb4full) ^ uint64_t(shift));
  return uint8_t(((h >> 32) * 24u) >> 32);
}
uint32_t permuted_digit(uint32_t z, int shift, uint8_t r) {
  return ((uint32_t(kDigitPermutations[r]) >> (2 * ((z >> shift) & 3u))) & 3u) << shift;
}
// An odd width's last digit, the single bit lo: flipped by a hash of the bits above it.
uint32_t tail_flip(uint32_t z, int lo, uint64_t key) {
  return uint32_t(mix64(key ^ ((uint64_t(z) >> (lo + 1)) * 0xc2b2ae3d27d4eb4full) ^ 0x5bd1e995ull) >> 63);
}

// scramble_digits(z, bits, lo, key) for z whose bits below lo are 0 and bits - lo even (a
// pixel's Morton digits above its block's sample bits), keeping the permutations above the
// first difference from the last z: a neighbouring pixel costs the digits that change (about
// 4/3) instead of all of them.
class PixelDigits {
 public:
  uint32_t operator()(uint32_t z, int bits, int lo, uint64_t key) {
    if (key != key_ || bits != bits_ || lo != lo_) key_ = key, bits_ = bits, lo_ = lo, valid_ = false;
    int shift = bits - 2;
    uint32_t out = 0;
    if (valid_) {
      if (z == z_) return out_;
      const int d = 31 - __builtin_clz(z ^ z_);  // >= lo
      shift = d - ((d - bits) & 1);              // the digit holding bit d keeps its permutation
      out = shift + 2 >= 32 ? 0u : out_ & (~0u << (shift + 2));
      out |= permuted_digit(z, shift, r_[std::size_t(shift) >> 1]);
      shift -= 2;
    }
    for (; shift >= lo; shift -= 2) {
      uint8_t& r = r_[std::size_t(shift) >> 1];
      r = digit_permutation(z, shift, key);
      out |= permuted_digit(z, shift, r);
    }
    z_ = z, out_ = out, valid_ = true;
    return out;
  }

 private:
  uint64_t key_ = 0;
  int bits_ = -1, lo_ = -1;
  bool valid_ = false;
  uint32_t z_ = 0, out_ = 0;
  std::array<uint8_t, 16> r_{};
};

// Byte b with its bits spread to the even positions of 16.
constexpr std::array<uint16_t, 256> kSpreadByte = [] {
  std::array<uint16_t, 256> t{};
  for (int v = 0; v < 256; ++v)
    for (int b = 0; b < 8; ++b) t[std::size_t(v)] = uint16_t(t[std::size_t(v)] | (((v >> b) & 1) << (2 * b)));
  return t;
}();

// The Morton index of (x, y): x in the even bits, y in the odd ones (16 bits each).
uint32_t interleave(uint32_t x, uint32_t y) {
  auto spread = [](uint32_t v) {
    return uint32_t(kSpreadByte[v & 255u]) | uint32_t(kSpreadByte[(v >> 8) & 255u]) << 16;
  };
  return spread(x) | spread(y) << 1;
}

constexpr uint64_t kKeySalt = 0x706f6973736f6e2dull;     // independent of zsobol's keys
constexpr uint64_t kShiftSalt = 0x73732d7368696674ull;   // a run's shift, apart from its table pick
constexpr uint64_t kSampleSalt = 0x73732d73616d706cull;  // a pixel's sample scramble

// One family's tables in progressive order: table t's point j at coords[t][j * dim + k].
struct OrderedTables {
  std::vector<std::vector<uint32_t>> coords;
  int dim = 2;
  int bits = 0;  // log2 of the points per table
};

void add_ordered(const SampleTable& t, Family f, OrderedTables* out) {
  for (const auto& c : t.coords) {
    std::string why;
    const auto order = progressive_order(c.data(), t.params.points, t.dim, &why);
    if (!order)
      throw UsageError(std::string("sampler poisson-ss: the ") + family_name(f) + " tables cannot be read in " +
                       "screen-space order: " + why);
    std::vector<uint32_t> v(c.size());
    for (uint32_t j = 0; j < t.params.points; ++j)
      for (int k = 0; k < t.dim; ++k) v[std::size_t(j) * t.dim + k] = c[std::size_t((*order)[j]) * t.dim + k];
    out->coords.push_back(std::move(v));
  }
  out->dim = t.dim;
  out->bits = std::countr_zero(t.params.points);
}

// A table set in progressive order. The 2-D families' tables are one pool, as in `poisson`
// (when they are of one size); `own` holds a 2-D family whose tables differ in size from the pixel's.
struct OrderedSet {
  OrderedTables plane, line;
  std::array<OrderedTables, kFamilyCount> own;
};

// Ordered once per table set and kept (a compare run makes a sampler per seed and spp).
std::shared_ptr<const OrderedSet> ordered_set(const TableSet& t) {
  static std::mutex mutex;
  static std::vector<std::pair<decltype(t.family), std::shared_ptr<const OrderedSet>>> done;
  std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [family, set] : done)
    if (family == t.family) return set;
  auto set = std::make_shared<OrderedSet>();
  const uint32_t pixel_points = t.family[int(Family::Pixel)]->params.points;
  for (int f = 0; f < kFamilyCount; ++f) {
    const SampleTable& ft = *t.family[std::size_t(f)];
    OrderedTables& to = ft.dim == 1                        ? set->line
                        : ft.params.points == pixel_points ? set->plane
                                                           : set->own[std::size_t(f)];
    add_ordered(ft, Family(f), &to);
  }
  done.emplace_back(t.family, set);
  return set;
}

class ScreenPoissonSampler final : public Sampler {
 public:
  ScreenPoissonSampler(uint64_t seed, const TableSet& t, const SamplerShape& o) : Sampler(seed) {
    const std::string me = "sampler poisson-ss: ";
    if (o.samples_per_pixel < 1) throw UsageError(me + "samples per pixel must be >= 1");
    if (o.width < 1 || o.height < 1) throw UsageError(me + "the image must have at least one pixel");
    m_ = pixel_order_bits(o.samples_per_pixel, 1, 1);
    k_ = pixel_order_bits(1, o.width, o.height) / 2;
    if (m_ > 31) throw UsageError(me + "at most 2^31 samples per pixel, got " + std::to_string(o.samples_per_pixel));
    if (bits() > kPixelOrderBits)
      throw UsageError(me + std::to_string(o.width) + " x " + std::to_string(o.height) + " pixels at " +
                       std::to_string(o.samples_per_pixel) + " samples per pixel need " + std::to_string(bits()) +
                       " bits of Morton and sample index, at most 32 (fewer samples per pixel or a smaller image)");
    const SampleTable& pixel = *t.family[int(Family::Pixel)];
    if (pixel.params.tile > 1)
      throw UsageError(me + "the pixel tables in " + t.dir.string() + " are tiled (" +
                       std::to_string(pixel.params.tile) + " x " + std::to_string(pixel.params.tile) +
                       " pixels); screen-space order needs untiled tables");
    set_ = ordered_set(t);
  }
  std::string name() const override { return sampler_name(SamplerKind::PoissonSS); }

  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    return unit_from_u32(fixed(px, py, uint64_t(index), f, bounce)[0]);
  }
  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    const auto v = fixed(px, py, uint64_t(index), f, bounce);
    return {unit_from_u32(v[0]), unit_from_u32(v[1])};
  }
  // A window block by block: the stream's cache is looked up once per block, not per value,
  // and a pixel's block of indices is one aligned block of a run, so its reads are contiguous.
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    const OrderedTables& t = tables(f);
    const int dim = t.dim;
    const uint32_t end = out->want, first = std::min(out->first, end);
    // Grown, never shrunk: nothing reads past the window, and zeroing it anew every pass cost
    // a twentieth of this function's time.
    if (out->own.size() < std::size_t(end - first) * std::size_t(dim)) out->own.resize(std::size_t(end - first) * dim);
    uint32_t* v = out->own.data();
    const uint64_t block_size = uint64_t(1) << m_;
    const uint32_t pixel = pixel_index(px, py);
    for (uint64_t b0 = first & ~(block_size - 1); b0 < end; b0 += block_size) {
      const uint64_t lo = std::max<uint64_t>(b0, first), hi = std::min<uint64_t>(b0 + block_size, end);
      const auto fill = [&](StreamCache& c) {
        if (dim == 2)
          fill_block<2>(c, pixel, uint32_t(lo - b0), uint32_t(hi - b0), f, t, v);
        else
          fill_block<1>(c, pixel, uint32_t(lo - b0), uint32_t(hi - b0), f, t, v);
      };
      if (unsigned(bounce) < unsigned(kCachedBounces)) {
        fill(cached_stream(f, bounce, b0 >> m_));
      } else {
        StreamCache local;  // (made only here: zeroing it was a twentieth of every call's time)
        local.key = block_key(f, bounce, b0 >> m_);
        fill(local);
      }
      v += std::size_t(hi - lo) * std::size_t(dim);
    }
    fill_prepared(out, first, end, dim, nullptr);
  }

  int64_t samples_available(int, int) const override { return INT64_MAX; }

 private:
  // A run of M indices: its table, its digital shift and whether its axes swap (both keep nets).
  struct Run {
    const uint32_t* coords = nullptr;
    uint32_t xr[2] = {0, 0};
    int swap = 0;
  };
  // What a thread keeps of a stream between values (pure functions of the keys they are
  // checked against, so values do not depend on what a thread computed before).
  struct StreamCache {
    PixelDigits pixel;
    uint64_t sampler = 0, block = 0, key = 0;  // the sampler (id_) and block whose key this is
    uint32_t run_id = UINT32_MAX;
    Run run;
  };

  // Value of sample `index` in 32-bit fixed point, per axis (1-D: axis 0).
  std::array<uint32_t, 2> fixed(int px, int py, uint64_t index, Family f, int bounce) const {
    const OrderedTables& t = tables(f);
    const uint64_t block = index >> m_;
    const uint32_t pixel = pixel_index(px, py), i = uint32_t(index) & low_mask();
    if (unsigned(bounce) < unsigned(kCachedBounces)) {
      StreamCache& c = cached_stream(f, bounce, block);
      return run_point(c, c.pixel(pixel, bits(), m_, c.key) | sample_bits(c.key, pixel, i), f, t);
    }
    // A bounce past the caches hashes every digit (what prepare's caches must agree with).
    StreamCache local;
    local.key = block_key(f, bounce, block);
    return run_point(local, scramble_digits(pixel, bits(), m_, local.key) | sample_bits(local.key, pixel, i), f, t);
  }

  // Per axis, position p of the stream's arrangement (c's block): the point of its run's table
  // under the run's shift and axis swap; c keeps the run between calls.
  std::array<uint32_t, 2> run_point(StreamCache& c, uint32_t p, Family f, const OrderedTables& t) const {
    if (c.run_id != run_of(p, t)) c.run_id = run_of(p, t), c.run = map_run(c.key, c.run_id, f, t);
    const uint32_t* at = c.run.coords + std::size_t(p & ((uint32_t(1) << t.bits) - 1)) * std::size_t(t.dim);
    if (t.dim == 1) return {at[0] ^ c.run.xr[0], 0};
    return {at[c.run.swap] ^ c.run.xr[0], at[c.run.swap ^ 1] ^ c.run.xr[1]};
  }

  // The sample digits of index i (< 2^m) of the pixel's block: base-4 digits from the top, each
  // permuted by one of the 24 permutations per node of the pixel's index tree (the digits above
  // it), as the pixel's digits are; an odd m ends in the single bit 0, flipped per pair. A
  // node's permutation is 16 bits of a hash of (pixel, level, node / 4), so four neighbouring
  // nodes share one hash (the pixel's tree costs (2^m - 1) / 12 hashes, not (2^m - 1) / 3).
  // (The pixel enters the node and tail hashes unmixed: each is a mix64 of its own.)
  uint64_t sample_seed(uint64_t key, uint32_t pixel) const {
    return key ^ kSampleSalt ^ (uint64_t(pixel) * 0x9e3779b97f4a7c15ull);
  }
  static uint64_t node_hash(uint64_t seed, int level, uint32_t quad) {
    return mix64(seed ^ (uint64_t(level + 1) * 0xd6e8feb86659fd93ull) ^ (uint64_t(quad) * 0xc2b2ae3d27d4eb4full));
  }
  static uint32_t node_perm_index(uint64_t h, uint32_t node) {  // h: node_hash of node / 4
    return ((uint32_t(h >> (16 * (node & 3u))) & 0xffffu) * 24u) >> 16;
  }
  static uint32_t node_perm(uint64_t h, uint32_t node) { return kDigitPermutations[node_perm_index(h, node)]; }
  static uint64_t tail_hash(uint64_t seed, uint32_t group) {  // the flips of pairs [64 group, 64 group + 64)
    return mix64(seed ^ 0xa0761d6478bd642full ^ (uint64_t(group) * 0xbf58476d1ce4e5b9ull));
  }
  uint32_t sample_bits(uint64_t key, uint32_t pixel, uint32_t i) const {
    const uint64_t seed = sample_seed(key, pixel);
    uint32_t out = 0;
    for (int l = 0, shift = m_ - 2; shift >= 0; ++l, shift -= 2) {
      const uint32_t node = i >> (shift + 2);
      out |= ((node_perm(node_hash(seed, l, node >> 2), node) >> (2 * ((i >> shift) & 3u))) & 3u) << shift;
    }
    if (m_ & 1) out |= (i & 1u) ^ uint32_t(tail_hash(seed, i >> 7) >> ((i >> 1) & 63u) & 1u);
    return out;
  }
  // out[i - a] = sample_bits(i) for a <= i < e (nested_digits.h), each level keeping the hash of
  // its last four nodes and the tail the hash of its last 64 pairs.
  void sample_bits(uint64_t seed, uint32_t a, uint32_t e, uint32_t* out) const {
    std::array<uint32_t, 16> quad;
    std::array<uint64_t, 16> hash;
    quad.fill(UINT32_MAX);
    const auto perm = [&](int l, uint32_t node) -> const std::array<uint32_t, 4>& {
      if (quad[std::size_t(l)] != node >> 2)
        quad[std::size_t(l)] = node >> 2, hash[std::size_t(l)] = node_hash(seed, l, node >> 2);
      return kSpreadPermutation[node_perm_index(hash[std::size_t(l)], node)];
    };
    uint32_t group = UINT32_MAX;
    uint64_t th = 0;
    const auto tail = [&](uint32_t i) {
      if (i >> 7 != group) group = i >> 7, th = tail_hash(seed, group);
      return (i & 1u) ^ uint32_t((th >> ((i >> 1) & 63u)) & 1u);
    };
    nested_digits(m_, 0, a, e, perm, tail, out);
  }

  // Indices [a, e) of the pixel's block of c's stream, D values each, into v: the pixel's
  // digits once (through c's cache), the window's sample digits, then the reads. The run is
  // copied into a local and written back after: the stores to v cannot alias a local, so it
  // stays in registers instead of being reloaded after every store.
  struct Runs {  // fill_block's copy of a stream's run
    uint64_t key;
    uint32_t run_id;
    Run run;
  };
  template <int D>
  void fill_block(StreamCache& c, uint32_t pixel, uint32_t a, uint32_t e, Family f, const OrderedTables& t,
                  uint32_t* v) const {
    const uint32_t top = c.pixel(pixel, bits(), m_, c.key);
    const uint32_t mask = (uint32_t(1) << t.bits) - 1;
    const uint64_t seed = sample_seed(c.key, pixel);
    Runs s{c.key, c.run_id, c.run};
    if (m_ <= t.bits && a < e) {
      // The block is an aligned block of one run: its points are contiguous in the run's
      // table (the window's in scrambled order). Asked for all at once, their cache misses
      // overlap instead of stalling the loop one by one.
      if (s.run_id != run_of(top, t)) s.run_id = run_of(top, t), s.run = map_run(s.key, s.run_id, f, t);
      const char* block = reinterpret_cast<const char*>(s.run.coords + std::size_t(top & mask) * D);
      const std::size_t bytes = std::min<std::size_t>(std::size_t(4) * D << m_, 4096);
      for (std::size_t b = 0; b < bytes; b += 64) __builtin_prefetch(block + b);
    }
    uint32_t low[256];
    for (uint32_t a0 = a; a0 < e; a0 += 256) {
      const uint32_t n = std::min<uint32_t>(256, e - a0);
      sample_bits(seed, a0, a0 + n, low);
      for (uint32_t j = 0; j < n; ++j, v += D) {
        const uint32_t p = top | low[j];
        if (s.run_id != run_of(p, t)) s.run_id = run_of(p, t), s.run = map_run(s.key, s.run_id, f, t);
        const uint32_t* q = s.run.coords + std::size_t(p & mask) * D;
        if constexpr (D == 1) {
          v[0] = q[0] ^ s.run.xr[0];
        } else {
          v[0] = q[s.run.swap] ^ s.run.xr[0];
          v[1] = q[s.run.swap ^ 1] ^ s.run.xr[1];
        }
      }
    }
    c.run_id = s.run_id, c.run = s.run;
  }

  // The thread's cache of a stream's block (bounce < kCachedBounces), keyed for it.
  StreamCache& cached_stream(Family f, int bounce, uint64_t block) const {
    // Four blocks per stream: a camera packet of 4 samples at 1 or 2 spp spans them.
    thread_local std::array<StreamCache, kFamilyCount * kCachedBounces * 4> cache;
    StreamCache& c = cache[(std::size_t(int(f) * kCachedBounces + bounce) << 2) + (block & 3)];
    if (c.sampler != id_ || c.block != block)
      c.sampler = id_, c.block = block, c.key = block_key(f, bounce, block), c.run_id = UINT32_MAX;
    return c;
  }

  const OrderedTables& tables(Family f) const {
    const OrderedSet& s = *set_;
    return family_dim(f) == 1 ? s.line : s.own[std::size_t(f)].coords.empty() ? s.plane : s.own[std::size_t(f)];
  }
  int bits() const { return 2 * k_ + m_; }
  uint32_t low_mask() const { return (uint32_t(1) << m_) - 1; }
  // The pixel's Morton index above the m sample bits; pixels outside the image wrap.
  uint32_t pixel_index(int px, int py) const {
    const uint32_t mask = (uint32_t(1) << k_) - 1;
    return k_ == 0 ? 0u : interleave(uint32_t(px) & mask, uint32_t(py) & mask) << m_;
  }
  uint32_t run_of(uint32_t p, const OrderedTables& t) const { return t.bits >= 32 ? 0 : p >> t.bits; }
  uint64_t block_key(Family f, int bounce, uint64_t block) const {
    return mix64(sample_stream_from_hash(seed_hash_, 0, 0, f, bounce) ^ kKeySalt ^ (block * 0x9e3779b97f4a7c15ull));
  }
  static Run map_run(uint64_t key, uint32_t run_id, Family f, const OrderedTables& t) {
    const uint64_t h = mix64(key ^ (uint64_t(run_id) * 0xbf58476d1ce4e5b9ull));
    const uint64_t s = mix64(h ^ kShiftSalt);
    const std::size_t table =
        std::size_t(((h >> 32) * uint64_t(std::min<std::size_t>(t.coords.size(), kPoolTables))) >> 32);
    Run r;
    r.coords = t.coords[table].data();
    r.xr[0] = uint32_t(s), r.xr[1] = uint32_t(s >> 32);
    r.swap = family_dim(f) == 2 ? int(h & 1) : 0;
    return r;
  }

  static constexpr int kCachedBounces = PixelSampleState::kCachedSalts;
  // Runs pick among a family's first 8 tables (64 KiB of 2-D points, 64 KiB of times): every
  // pixel reads a block of its own, so with the whole pool of 64 the reads missed L2 (perf: half
  // of the sampler's time). Each run's digital shift still makes every value uniform.
  static constexpr std::size_t kPoolTables = 8;
  static inline std::atomic<uint64_t> next_id_{1};
  uint64_t id_ = next_id_.fetch_add(1);  // tells the thread caches' runs of one sampler from another's
  int m_ = 0, k_ = 0;
  std::shared_ptr<const OrderedSet> set_;
};

}  // namespace

uint32_t scramble_digits(uint32_t z, int hi, int lo, uint64_t key) {
  uint32_t out = 0;
  int shift = hi - 2;
  for (; shift >= lo; shift -= 2) out |= permuted_digit(z, shift, digit_permutation(z, shift, key));
  if (shift == lo - 1) out |= (((z >> lo) & 1u) ^ tail_flip(z, lo, key)) << lo;
  return out;
}

std::unique_ptr<Sampler> make_screen_poisson_sampler(uint64_t seed, const TableSet& tables, const SamplerShape& shape) {
  return std::make_unique<ScreenPoissonSampler>(seed, tables, shape);
}

}  // namespace pdrt
