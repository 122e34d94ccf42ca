// `poisson` and `poisson-065` samplers (docs/sampling.md, "Decorrelation"). Non-pixel
// families: a pixel's streams of one family take distinct tables (a per-pixel permutation of
// the tables indexed by the bounce salt), each with its own symmetry of the square and its
// own shift: for `poisson` a digital shift, which keeps the (0,2) strata and makes every
// value uniform, read through a per-stream index shuffle (PoissonShift has the alternatives
// and why they are not the default); for `poisson-065` a toroidal (Cranley–Patterson)
// shift, which keeps the tables' distances. Pixel family: untiled
// tables are read like the other families; a P x P tile instance (P > 1) takes a table, a
// symmetry and a shift of the tile pattern on its torus, and a pixel's samples are the
// shifted pattern's points inside it, in rank order. Sample i is the i-th point of the
// stream's prefix, so raising a pixel's sample count only appends samples (McCool §5.1).
#include "sampling/samplers/poisson_sampler.h"

#include "sampling/core/cache_dir.h"
#include "sampling/core/errors.h"
#include "sampling/core/install_paths.h"
#include "sampling/core/rng.h"
#include "sampling/core/warnings.h"
#include "sampling/samplers/screen_keys.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <utility>
#include <vector>

namespace pdrt {
namespace {

constexpr double kFixed = 0x1.0p-32;
constexpr uint64_t kShiftSalt = 0x73686966742d6370ull;   // the shift is independent of table and symmetry
constexpr uint64_t kScreenSalt = 0x7363726e2d6b6579ull;  // poisson-bn's per-stream tile offset and shift

// Integer pixel version of the 8 symmetries of the square (bit 0 swaps the axes, bits 1 and
// 2 flip x and y after the swap): inverse of the symmetry on a P x P grid.
void inverse_symmetry_pixel(unsigned sym, int P, int& a, int& b) {
  if (sym & 2) a = P - 1 - a;
  if (sym & 4) b = P - 1 - b;
  if (sym & 1) std::swap(a, b);
}

// Table index from the top hash bits by multiply-shift (no division in the lookup path).
uint32_t pick(uint64_t h, uint32_t n) { return uint32_t(((h >> 32) * uint64_t(n)) >> 32); }

// A keyed permutation of [0, n): rounds of xor, odd multiply and xor-shift, each a bijection
// modulo 2^bits, then cycle walking into [0, n) (Black & Rogaway 2002). The rounds' keys are
// hashed from one key once (PermuteKey), as every stream of a pixel permutes with the same.
struct PermuteKey {
  uint64_t round[3];
};
PermuteKey permute_key(uint64_t key) {
  PermuteKey k;
  for (int r = 0; r < 3; ++r) k.round[r] = mix64(key + uint64_t(r) * 0x9e3779b97f4a7c15ull);
  return k;
}
uint32_t permute(uint32_t i, uint32_t n, const PermuteKey& key) {
  if (n <= 1) return 0;
  const int bits = 32 - __builtin_clz(n - 1);
  const uint32_t mask = bits >= 32 ? ~0u : (1u << bits) - 1;
  do {
    for (uint64_t k : key.round) {
      i = (i ^ uint32_t(k)) & mask;
      i = (i * (uint32_t(k >> 32) | 1u)) & mask;
      i ^= i >> ((bits + 1) / 2);
    }
  } while (i >= n);
  return i;
}

// std::has_single_bit without the popcount library call of a build for baseline x86-64.
constexpr bool power_of_two(uint32_t n) { return n && !(n & (n - 1)); }

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
int mod(int a, int b) { return a - floor_div(a, b) * b; }

class PoissonSampler final : public Sampler {
 public:
  PoissonSampler(uint64_t seed, const TableSet& t, PoissonOptions o) : Sampler(seed), tables_(t), opt_(o) {
    // `poisson`'s untiled 2-D families hold tables of one kind (owen-pd, same size), so they
    // are read as one pool: 4x the tables per stream for the same generation time, and no two
    // 2-D streams of a path share one (docs/sampling.md, "Tables without replacement").
    if (stratified() && !tiled()) {
      const SampleTable& lens = *t.family[int(Family::Lens)];
      for (Family f : kPlaneFamilies) {
        const SampleTable& ft = *t.family[int(f)];
        if (ft.dim != 2 || ft.params.points != lens.params.points ||
            ft.params.construction != lens.params.construction) {
          pool_.clear();
          break;
        }
        for (const auto& c : ft.coords) pool_.push_back(c.data());
      }
    }
    if (o.screen_keys_spp > 0) {
      if (pool_.empty())
        throw UsageError("poisson-bn needs the poisson table set's untiled tables of one size per 2-D family (" +
                         t.dir.string() + ")");
      std::vector<const uint32_t*> time;
      for (const auto& c : t.family[int(Family::Time)]->coords) time.push_back(c.data());
      const int spp = int(std::min<int64_t>(o.screen_keys_spp, 64));
      plane_keys_ = &cached_screen_keys(pool_, 2, spp);
      time_keys_ = &cached_screen_keys(time, 1, spp);
      for (int f = 0; f < kFamilyCount; ++f)
        for (int b = 0; b < PixelSampleState::kCachedSalts; ++b) key_places_[f][b] = key_place(Family(f), b);
    }
  }
  std::string name() const override { return plane_keys_ ? "poisson-bn" : table_set_name(tables_.kind); }

  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    if (f == Family::Pixel && tiled()) {
      thread_local PreparedStream p;
      p.want = uint32_t(std::min<int64_t>(index + 1, INT32_MAX));
      pixel_stream(px, py, bounce, &p);
      return {p.value(index, 0), p.value(index, 1)};
    }
    PreparedStream p;
    const uint32_t m = tables_.family[int(f)]->params.points;
    if (f == Family::Pixel && uint64_t(index) >= m) warn_past_prefix(px, py, m);
    const auto [round, j] = split_index(uint64_t(index), m);
    const uint64_t h = map_stream(px, py, f, bounce, round, &p);
    index = table_index(f, h, round, j);
    return {p.value(index, 0), p.value(index, 1)};
  }

  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    if (f != Family::Time) return get_2d(px, py, index, f, bounce)[0];
    PreparedStream p;
    const uint32_t m = tables_.family[int(f)]->params.points;
    const auto [round, j] = split_index(uint64_t(index), m);
    const uint64_t h = map_stream(px, py, f, bounce, round, &p);
    return p.value(table_index(f, h, round, j), 0);
  }

  // get_2d/get_1d read values through the same PreparedStream (and, for poisson, the same
  // index shuffle), so the fast path is exact.
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    if (f == Family::Pixel && tiled()) return pixel_stream(px, py, bounce, out);
    const uint64_t h = map_stream(px, py, f, bounce, 0, out);
    if (!stratified() || !power_of_two(out->count)) return;
    // poisson: the window's points of the table read through the stream's index shuffle,
    // stored per stream; the stream's map (symmetry and shift) stays as map_stream set it, so
    // a value is the same double as get_2d's.
    const uint32_t* table = out->coords;
    const uint32_t n = std::min(out->want, out->count), first = std::min(out->first, n), m = n - first;
    const int dim = family_dim(f);
    uint32_t few[64];  // a low-spp pass's window needs no heap
    thread_local std::vector<uint32_t> many;
    if (m > 64) many.resize(m);
    uint32_t* perm = m > 64 ? many.data() : few;
    IndexShuffle(shuffle_key(h, 0)).fill(first, n, perm);
    out->own.resize(std::size_t(m) * dim);
    uint32_t* own = out->own.data();
    if (dim == 2) {
      for (uint32_t i = 0; i < m; ++i) std::memcpy(own + 2 * std::size_t(i), table + 2 * std::size_t(perm[i]), 8);
    } else {
      for (uint32_t i = 0; i < m; ++i) own[i] = table[perm[i]];
    }
    out->coords = own;
    out->base = first;
    out->grows = n < out->count;
    out->count = n;
  }

  // Tiled pixel tables merge cells per pixel; every other stream points into a table or,
  // for `poisson`, is a shuffled copy of one (about 1.5 ns a value against 30-40 ns for a value
  // asked alone, so preparing pays even for the deep streams few samples reach).
  bool prepare_computes(Family f) const override { return f == Family::Pixel && tiled(); }

  int64_t samples_available(int px, int py) const override {
    int64_t n = INT64_MAX;
    if (tiled()) {
      thread_local PreparedStream p;
      p.want = UINT32_MAX;
      pixel_prefix(px, py, 0, 0, UINT32_MAX, &p.own);
      n = int64_t(p.own.size() / 2);
    }
    for (int f = 0; f < kFamilyCount; ++f) n = std::min<int64_t>(n, tables_.family[f]->params.points);
    return n;
  }

 private:
  // Non-pixel stream `bounce` of pixel (px, py), values [round * M, (round + 1) * M). Round 0
  // of salts below the table count T: table perm(bounce) of the pixel's permutation, so the
  // streams of one path never share a table. Deeper salts reuse the permutation under
  // another key, and later rounds pick by hash: such streams differ only by symmetry and shift.
  // Returns the stream's hash (stream(px, py, f, bounce)).
  uint64_t map_stream(int px, int py, Family f, int bounce, uint64_t round, PreparedStream* out) const {
    const uint64_t hs = stream(px, py, f, bounce);
    if (plane_keys_ && round == 0) return keyed_stream(px, py, f, bounce, hs, out);
    const SampleTable& t = *tables_.family[int(f)];
    const bool pooled = !pool_.empty() && f != Family::Time;
    // Pooled: the 2-D families share one permutation of the pool, salt b of family f at
    // slot 4 b + f's place, so no two 2-D streams of a path share a table up to depth 16.
    const uint32_t T = pooled ? uint32_t(pool_.size()) : t.table_count();
    const uint32_t b = pooled ? 4 * uint32_t(bounce) + plane_place(f) : uint32_t(bounce);
    const uint32_t slot = power_of_two(T) ? b & (T - 1) : b % T,
                   group = power_of_two(T) ? b >> std::countr_zero(T) : b / T;
    uint64_t h = hs;
    uint32_t table;
    if (round == 0) {
      // The pixel's allocation, shared by its salts (and, pooled, by its 2-D families).
      table = permute(slot, T, allocation(px, py, pooled ? Family::Pixel : f, group));
    } else {
      h = hash_combine(h, round);
      table = pick(h, T);
    }
    const unsigned sym = f == Family::Time ? (unsigned(h) & 1u) << 1 : unsigned(h) & 7u;  // 1-D: the flip only
    const uint64_t s = opt_.shift ? mix64(h ^ kShiftSalt) : 0;
    read_table(t, pooled ? pool_[table] : t.coords[table].data(), out);
    const bool swap = sym & 1;
    for (int k = 0; k < 2; ++k) {
      const bool flip = sym & (2u << k);
      out->src[k] = uint8_t(swap ? 1 - k : k);
      const uint32_t r = uint32_t(s >> (32 * out->src[k]));  // the shift belongs to the table's axis
      const PoissonShift mode = shift_of(f);
      if (mode != PoissonShift::Toroidal) {
        // A flip as the complement 1 - 2^-32 - x and a digital shift: each maps every
        // elementary interval onto one, so the strata survive (a toroidal shift would cut the
        // stratum that wraps). Isometric: only the top bit (x + 1/2 on the torus) and the
        // bits below 2^-12 are shifted; the first two are isometries of the torus and the
        // last moves a point by < 2^-12, so the tables' distances survive too (a digital shift
        // of the bits between would swap dyadic blocks and bring far points together).
        const uint32_t keep = mode == PoissonShift::Digital ? ~0u : 0x80000000u | (~0u >> kShiftExactBits);
        out->xr[k] = (r & keep) ^ (flip ? ~0u : 0u), out->add[k] = 0, out->off[k] = 0.0, out->mul[k] = kFixed;
      } else {
        out->xr[k] = 0, out->add[k] = r;
        out->off[k] = flip ? 1.0 : 0.0;
        out->mul[k] = flip ? -kFixed : kFixed;
      }
    }
    return hs;
  }

  // `out` reads all of `coords`, one of table family t's tables (its axis map is the caller's).
  static void read_table(const SampleTable& t, const uint32_t* coords, PreparedStream* out) {
    out->coords = coords;
    out->base = 0;
    out->count = t.params.points;
    out->shift = t.dim == 2 ? 1 : 0;
    out->grows = false;
  }

  // poisson-bn's round 0: the key of the pixel's place in the tile (offset per stream), under a
  // digital shift uniform per (seed, family, bounce): every value is uniform over seeds and the
  // keys' relations between neighbouring pixels stay.
  uint64_t keyed_stream(int px, int py, Family f, int bounce, uint64_t hs, PreparedStream* out) const {
    const SampleTable& t = *tables_.family[int(f)];
    const ScreenKeyTile& tile = f == Family::Time ? *time_keys_ : *plane_keys_;
    const KeyPlace place = unsigned(bounce) < unsigned(PixelSampleState::kCachedSalts) ? key_places_[int(f)][bounce]
                                                                                       : key_place(f, bounce);
    const ScreenKey& k = tile.at(px + place.ox, py + place.oy);
    read_table(t, f == Family::Time ? t.coords[k.table].data() : pool_[k.table], out);
    for (int a = 0; a < 2; ++a) {
      out->src[a] = uint8_t(t.dim == 2 && k.swap ? 1 - a : t.dim == 2 ? a : 0);
      out->xr[a] = k.x[a] ^ uint32_t(place.shift >> (32 * a)), out->add[a] = 0, out->off[a] = 0.0, out->mul[a] = kFixed;
    }
    return hs;
  }

  // The keys of the allocation of pixel (px, py)'s streams of `fam` (Pixel: the 2-D pool) for
  // salts [group T, (group + 1) T). A pixel's streams are prepared one after another, so the
  // thread keeps the last keys it hashed per family (a path alternates the pool and time).
  const PermuteKey& allocation(int px, int py, Family fam, uint32_t group) const {
    struct Memo {
      uint64_t sampler = 0;
      int px = 0, py = 0;
      uint32_t group = 0;
      PermuteKey key;
    };
    thread_local Memo memos[kFamilyCount];
    Memo& memo = memos[int(fam)];
    if (memo.sampler != instance_ || memo.px != px || memo.py != py || memo.group != group)
      memo = {instance_, px, py, group, permute_key(hash_combine(stream(px, py, fam, -1), group))};
    return memo.key;
  }

  // The pixel family: round r of a pixel is the points of its tile's pattern r (table,
  // symmetry and toroidal shift by hash of the tile and r) inside the pixel, in rank order;
  // rounds follow each other, so no sample repeats. Values are stored with the symmetry
  // applied (a flip is the negation modulo 2^32, the same point on the pixel's torus).
  void pixel_stream(int px, int py, int bounce, PreparedStream* out) const {
    out->own.clear();
    for (uint64_t round = 0; out->own.size() / 2 < out->want && round < (1u << 20); ++round) {
      if (round == 1) warn_past_prefix(px, py, out->own.size() / 2);
      pixel_prefix(px, py, bounce, round, out->want - uint32_t(out->own.size() / 2), &out->own);
    }
    out->coords = out->own.data();
    out->count = uint32_t(out->own.size() / 2);
    out->shift = 1;
    out->grows = true;
    for (int k = 0; k < 2; ++k)
      out->src[k] = uint8_t(k), out->xr[k] = 0, out->add[k] = 0, out->off[k] = 0.0, out->mul[k] = kFixed;
  }

  // Appends up to `want` points of round `round` of pixel (px, py). The shifted pattern's
  // pixel is up to four cells of the stored one: a stored offset c of axis k lands in the
  // pixel when c + F_k wraps (the cell before) or not (the cell itself), at offset
  // uint32(c + F_k). The cells' rank orders merge by radius (non-increasing in rank), ties
  // by cell, so every prefix lies in a global prefix of the pattern: Poisson-disk at its radius.
  void pixel_prefix(int px, int py, int bounce, uint64_t round, uint32_t want, std::vector<uint32_t>* out) const {
    const SampleTable& t = *tables_.family[int(Family::Pixel)];
    const int P = int(t.params.tile);
    const int tx = floor_div(px, P), ty = floor_div(py, P);
    uint64_t h = stream(tx, ty, Family::Pixel, bounce);
    if (round) h = hash_combine(h, round);
    const uint32_t k = pick(h, t.table_count());
    const unsigned sym = unsigned(h) & 7u;
    uint32_t F[2] = {0, 0};
    int I[2] = {0, 0};
    if (opt_.shift) {
      const uint64_t s = mix64(h ^ kShiftSalt), s2 = mix64(s);
      F[0] = uint32_t(s), F[1] = uint32_t(s >> 32);
      I[0] = int(pick(s2, uint32_t(P))), I[1] = int(pick(s2 << 32, uint32_t(P)));
    }
    int oa = px - tx * P, ob = py - ty * P;
    inverse_symmetry_pixel(sym, P, oa, ob);
    struct Piece {
      uint32_t at, end;
      bool wrap[2];
    } pieces[4];
    const uint32_t* c = t.coords[k].data();
    const float* r = t.radius[k].data();
    for (int j = 0; j < 4; ++j) {
      const bool wx = j & 1, wy = j & 2;
      const int cx = mod(oa - I[0] - int(wx), P), cy = mod(ob - I[1] - int(wy), P);
      const uint32_t cell = uint32_t(cy * P + cx);
      pieces[j].at = t.cell_start[k][cell];
      pieces[j].end = pieces[j].at + t.cell_count[k][cell];
      if ((wx && F[0] == 0) || (wy && F[1] == 0)) pieces[j].at = pieces[j].end;  // no point wraps
      pieces[j].wrap[0] = wx, pieces[j].wrap[1] = wy;
    }
    auto lands = [&](const Piece& p) {
      for (int a = 0; a < 2; ++a)
        if ((uint32_t(c[2 * p.at + a] + F[a]) < F[a]) != p.wrap[a]) return false;
      return true;
    };
    for (Piece& p : pieces)
      while (p.at < p.end && !lands(p)) ++p.at;
    for (uint32_t n = 0; n < want; ++n) {
      int best = -1;
      for (int j = 0; j < 4; ++j)
        if (pieces[j].at < pieces[j].end && (best < 0 || r[pieces[j].at] > r[pieces[best].at])) best = j;
      if (best < 0) break;
      Piece& p = pieces[best];
      uint32_t v[2] = {c[2 * p.at] + F[0], c[2 * p.at + 1] + F[1]};
      if (sym & 1) std::swap(v[0], v[1]);
      if (sym & 2) v[0] = 0u - v[0];
      if (sym & 4) v[1] = 0u - v[1];
      out->push_back(v[0]);
      out->push_back(v[1]);
      ++p.at;
      while (p.at < p.end && !lands(p)) ++p.at;
    }
  }

  void warn_past_prefix(int px, int py, std::size_t n) const {
    static std::atomic<bool> warned{false};
    if (warned.exchange(true)) return;
    char line[240];
    std::snprintf(line, sizeof line,
                  "pdrt: %s: pixel (%d, %d) took more than its %zu Poisson-disk samples; later samples continue "
                  "in another table and shift (docs/sampling.md)",
                  name().c_str(), px, py, n);
    warn(line, "poisson: past the prefix");
  }

  // Sample index i of a stream of m-point tables: round i / m, point i mod m (by mask where m is
  // a power of two, as the default tables are: a 64-bit division per value otherwise).
  static std::pair<uint64_t, uint64_t> split_index(uint64_t i, uint32_t m) {
    if (power_of_two(m)) return {i >> std::countr_zero(m), i & (m - 1)};
    return {i / m, i % m};
  }

  // `poisson` reads every stream through its own index shuffle (as jitter and sobol do): its
  // stratified tables visit their strata in related orders (progressive jitter's fixed
  // parent order in time, Sobol's index structure in 2-D) that a digital shift does not
  // change, so two streams of a pixel would otherwise move in lockstep. Power-of-two prefixes
  // keep their point sets, so their strata and distances. `poisson-065` keeps the tables'
  // own order, which is what makes its every prefix Poisson-disk at rho 0.65.
  static uint64_t shuffle_key(uint64_t stream_hash, uint64_t round) {
    return hash_combine(stream_hash, round ^ 0x73687566666c6532ull);
  }
  // j's place in the table of stream hash h (map_stream's). (The shuffle keeps [0, 2^k) but not
  // a shorter table's range: those keep their order.)
  int64_t table_index(Family f, uint64_t h, uint64_t round, uint64_t j) const {
    // (Indices 0 and 1 are their own shuffle: no key to hash.)
    if (j < 2 || !stratified() || !power_of_two(tables_.family[int(f)]->params.points)) return int64_t(j);
    return int64_t(IndexShuffle(shuffle_key(h, round))(j));
  }

  // Pixel tables of a P x P tile (P > 1) keep the Poisson-disk property across pixel borders;
  // the default P = 1 gives each pixel its own pattern on its torus like the other families.
  bool tiled() const { return tables_.family[int(Family::Pixel)]->params.tile > 1; }
  // `poisson`'s tables are stratified and read through the index shuffle.
  bool stratified() const { return tables_.kind == TableSetKind::Poisson; }
  PoissonShift shift_of(Family f) const {
    if (!stratified()) return PoissonShift::Toroidal;
    return f == Family::Pixel ? opt_.pixel : f == Family::Time ? opt_.time : opt_.plane;
  }

  // poisson-bn: stream (f, bounce)'s offset in the key tile and its digital shift, constants
  // of the sampler (kept for the cached salts, made on the fly past them).
  struct KeyPlace {
    int ox = 0, oy = 0;
    uint64_t shift = 0;
  };
  KeyPlace key_place(Family f, int bounce) const {
    const ScreenKeyTile& tile = f == Family::Time ? *time_keys_ : *plane_keys_;
    const uint64_t hk = mix64(stream(INT32_MIN, INT32_MIN, f, bounce) ^ kScreenSalt);
    return {int((hk & 0xffffffffu) % uint32_t(tile.size)), int((hk >> 32) % uint32_t(tile.size)),
            mix64(hk ^ kShiftSalt)};
  }

  static constexpr Family kPlaneFamilies[] = {Family::Pixel, Family::Lens, Family::Light, Family::Gloss};
  static uint32_t plane_place(Family f) {
    return f == Family::Pixel ? 0 : f == Family::Lens ? 1 : f == Family::Light ? 2 : 3;
  }

  TableSet tables_;
  PoissonOptions opt_;
  std::vector<const uint32_t*> pool_;          // `poisson`'s 2-D tables of every family, when pooled
  const ScreenKeyTile* plane_keys_ = nullptr;  // poisson-bn: the 2-D families' keys
  const ScreenKeyTile* time_keys_ = nullptr;   // and the time family's
  KeyPlace key_places_[kFamilyCount][PixelSampleState::kCachedSalts];
};

bool complete(const std::filesystem::path& dir, TableSetKind kind) {
  for (int f = 0; f < kFamilyCount; ++f)
    if (!std::filesystem::exists(dir / table_file_name(Family(f), kind))) return false;
  return true;
}

}  // namespace

TableSet load_tables(const std::filesystem::path& dir, TableSetKind kind) {
  TableSet set;
  set.dir = dir;
  set.kind = kind;
  for (int f = 0; f < kFamilyCount; ++f) {
    Family fam = Family(f);
    const std::filesystem::path file = dir / table_file_name(fam, kind);
    auto t = std::make_shared<const SampleTable>(read_table(file, &fam));
    // The randomisation relies on the construction: a digital shift keeps owen-pd's strata,
    // a toroidal one stratified-pd's distances; another set's tables would be read wrongly.
    const Construction want = table_set_construction(kind, fam);
    if (t->params.construction != want)
      throw InputError(file.string() + ": construction is " + construction_name(t->params.construction) + ", the " +
                       table_set_name(kind) + " sampler's " + family_name(fam) + " tables must be " +
                       construction_name(want));
    set.family[f] = std::move(t);
  }
  return set;
}

TableSet cached_tables(const std::filesystem::path& dir, TableSetKind kind) {
  if (complete(dir, kind)) return load_tables(dir, kind);
  // Generated here and kept in memory; the cache only saves the next run the work. A cache
  // that cannot be written costs one warning (each file is written atomically, so none is
  // left half-written), never the render.
  warn(std::string("pdrt: generating the ") + table_set_name(kind) + " sample tables into " + dir.string() + " (once)");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::string failed = ec ? ec.message() : "";
  TableSet set;
  set.dir = dir;
  set.kind = kind;
  for (const TableParams& p : default_table_params(kind)) {
    auto t = std::make_shared<const SampleTable>(generate_table(p));
    if (failed.empty()) try {
        write_table(dir / table_file_name(p.family, kind), *t);
      } catch (const std::exception& e) {
        failed = e.what();
      }
    set.family[int(p.family)] = std::move(t);
  }
  if (!failed.empty())
    warn("pdrt: warning: " + dir.string() + ": cannot write the table cache (" + failed +
         "); using the tables generated in memory, which the next run generates again");
  return set;
}

const TableSet& default_tables(TableSetKind kind) {
  static std::once_flag once[2];
  static TableSet sets[2];
  const int i = int(kind);
  std::call_once(once[i], [kind, i] {
    TableSet& set = sets[i];
    if (const char* env = std::getenv("PDRT_TABLES"); env && *env) {
      set = load_tables(env, kind);
      return;
    }
    if (auto installed = installed_path("share/pdrt/tables"); installed && complete(*installed, kind)) {
      set = load_tables(*installed, kind);
      return;
    }
#ifdef PDRT_BUILD_TABLE_DIR
    if (complete(PDRT_BUILD_TABLE_DIR, kind)) {
      set = load_tables(PDRT_BUILD_TABLE_DIR, kind);
      return;
    }
#endif
    // The cache key names the file format and the generation rule (g2: draws that miss the
    // rho bar are redrawn; g3: balanced 1-D time tables; g4: 2048 of them; g5: 64 time tables;
    // g6: untiled pixel tables; g7: stratified-pd and owen-pd sets; g8: owen-pd is `poisson`,
    // stratified-pd `poisson-065`), so an older pdrt's cache is not reused.
    set = cached_tables(cache_dir() / ("tables-v" + std::to_string(kTableVersion) + "-g8-seed1"), kind);
  });
  return sets[i];
}

std::unique_ptr<Sampler> make_poisson_sampler(uint64_t seed, const TableSet& tables, PoissonOptions options) {
  return std::make_unique<PoissonSampler>(seed, tables, options);
}

}  // namespace pdrt
