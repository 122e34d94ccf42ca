// `poisson` sampler: a hash of (pixel or tile, family, bounce, seed) picks a table and one of
// the 8 symmetries of the square (flips and axis swap), which keep both the Poisson-disk
// radius and the pixel grid; optionally a toroidal shift. Sample i is the i-th point of the
// chosen prefix, so raising a pixel's sample count only appends samples (McCool §5.1).
#include "sampling/samplers/poisson_sampler.h"

#include "sampling/core/cache_dir.h"
#include "sampling/core/errors.h"
#include "sampling/core/rng.h"

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <mutex>

namespace pdrt {
namespace {

constexpr double kFixed = 0x1.0p-32;

// The 8 symmetries of [0, size)^2: bit 0 swaps the axes, bits 1 and 2 flip x and y (after
// the swap).
Vec2 apply_symmetry(Vec2 p, unsigned sym, double size) {
  if (sym & 1) std::swap(p[0], p[1]);
  if (sym & 2) p[0] = size - p[0];
  if (sym & 4) p[1] = size - p[1];
  return p;
}

// Integer pixel version: inverse of the symmetry on a P x P grid.
void inverse_symmetry_pixel(unsigned sym, int P, int& a, int& b) {
  if (sym & 2) a = P - 1 - a;
  if (sym & 4) b = P - 1 - b;
  if (sym & 1) std::swap(a, b);
}

// Table index from the top hash bits by multiply-shift (no division in the lookup path).
uint32_t pick(uint64_t h, uint32_t n) { return uint32_t(((h >> 32) * uint64_t(n)) >> 32); }

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

class PoissonSampler final : public Sampler {
 public:
  PoissonSampler(uint64_t seed, const TableSet& t, PoissonOptions o) : Sampler(seed), tables_(t), opt_(o) {}
  std::string name() const override { return "poisson"; }

  Vec2 get_2d(int px, int py, int64_t index, Family f, int bounce) const override {
    if (f == Family::Pixel) return pixel_sample(px, py, index, bounce);
    const SampleTable& t = *tables_.family[int(f)];
    uint64_t h = stream(px, py, f, bounce);
    const uint32_t m = t.params.points;
    // Past the table's length, continue in another table (no longer one Poisson-disk prefix).
    if (uint64_t(index) >= m) h = hash_combine(h, uint64_t(index) / m), index %= m;
    const uint32_t* c = &t.coords[pick(h, t.table_count())][std::size_t(index) * 2];
    Vec2 p = apply_symmetry({c[0] * kFixed, c[1] * kFixed}, unsigned(h) & 7u, 1.0);
    if (opt_.toroidal_shift) {
      uint64_t s = mix64(h);
      p[0] += double(s >> 40) * 0x1.0p-24;
      p[1] += double((s >> 16) & 0xffffff) * 0x1.0p-24;
      p[0] -= std::floor(p[0]);
      p[1] -= std::floor(p[1]);
    }
    return {clamp_to_unit(p[0]), clamp_to_unit(p[1])};
  }

  double get_1d(int px, int py, int64_t index, Family f, int bounce) const override {
    if (f != Family::Time) return get_2d(px, py, index, f, bounce)[0];
    const SampleTable& t = *tables_.family[int(f)];
    uint64_t h = stream(px, py, f, bounce);
    const uint32_t m = t.params.points;
    if (uint64_t(index) >= m) h = hash_combine(h, uint64_t(index) / m), index %= m;
    double x = t.coords[pick(h, t.table_count())][std::size_t(index)] * kFixed;
    if (h & 1) x = 1.0 - x;  // the 1-D symmetry
    if (opt_.toroidal_shift) x += double(mix64(h) >> 40) * 0x1.0p-24, x -= std::floor(x);
    return clamp_to_unit(x);
  }

  // get_2d/get_1d/pixel_sample with the per-stream part done once. Their steps (offset,
  // flip, subtract the pixel) are exact in double for 32-bit fixed point and tiles below
  // 2^20 pixels, so one multiply-add by +-2^-32 gives the same bits.
  void prepare(int px, int py, Family f, int bounce, PreparedStream* out) const override {
    if (opt_.toroidal_shift && f != Family::Pixel) {
      out->coords = nullptr;
      return;
    }
    const SampleTable& t = *tables_.family[int(f)];
    out->shift = t.dim == 2 ? 1 : 0;
    unsigned sym;
    double base[2] = {0, 0}, origin[2] = {0, 0}, size = 1.0;
    if (f == Family::Pixel) {
      const int P = int(t.params.tile);
      int a, b, oa, ob;
      uint32_t k, cell;
      locate(px, py, bounce, t, P, a, b, k, cell, sym);
      oa = a, ob = b;
      inverse_symmetry_pixel(sym, P, oa, ob);
      out->coords = &t.coords[k][std::size_t(t.cell_start[k][cell]) * 2];
      out->count = t.cell_count[k][cell];
      base[0] = oa, base[1] = ob, origin[0] = a, origin[1] = b, size = double(P);
    } else {
      uint64_t h = stream(px, py, f, bounce);
      out->coords = t.coords[pick(h, t.table_count())].data();
      out->count = t.params.points;
      sym = f == Family::Time ? (unsigned(h) & 1u) << 1 : unsigned(h) & 7u;  // 1-D: the flip only
    }
    const bool swap = sym & 1;
    if (swap) std::swap(base[0], base[1]);
    for (int k = 0; k < 2; ++k) {
      const bool flip = sym & (2u << k);
      out->src[k] = uint8_t(swap ? 1 - k : k);
      out->off[k] = (flip ? size - base[k] : base[k]) - origin[k];
      out->mul[k] = flip ? -kFixed : kFixed;
    }
  }

  int64_t samples_available(int px, int py) const override {
    const SampleTable& t = *tables_.family[int(Family::Pixel)];
    int P = int(t.params.tile), a, b;
    uint32_t k, cell;
    unsigned sym;
    locate(px, py, 0, t, P, a, b, k, cell, sym);
    int64_t n = t.cell_count[k][cell];
    for (int f = 1; f < kFamilyCount; ++f) n = std::min<int64_t>(n, tables_.family[f]->params.points);
    return n;
  }

 private:
  // The pixel family: one table pattern covers a P x P tile of pixels; the tile instance
  // chooses table and symmetry, so neighbouring pixels of a tile share one Poisson-disk
  // pattern and do not clump at their borders.
  void locate(int px, int py, int bounce, const SampleTable& t, int P, int& a, int& b, uint32_t& k, uint32_t& cell,
              unsigned& sym) const {
    int tx = floor_div(px, P), ty = floor_div(py, P);
    uint64_t h = stream(tx, ty, Family::Pixel, bounce);
    k = pick(h, t.table_count());
    sym = unsigned(h) & 7u;
    a = px - tx * P, b = py - ty * P;
    int oa = a, ob = b;
    inverse_symmetry_pixel(sym, P, oa, ob);
    cell = uint32_t(ob * P + oa);
  }

  Vec2 pixel_sample(int px, int py, int64_t index, int bounce) const {
    const SampleTable& t = *tables_.family[int(Family::Pixel)];
    const int P = int(t.params.tile);
    int a, b;
    uint32_t k, cell;
    unsigned sym;
    locate(px, py, bounce, t, P, a, b, k, cell, sym);
    uint32_t count = t.cell_count[k][cell];
    uint64_t i = uint64_t(index);
    if (i >= count) i %= count;  // past the prefix: repeat (samples_available says where)
    const uint32_t* c = &t.coords[k][std::size_t(t.cell_start[k][cell] + i) * 2];
    int oa = a, ob = b;
    inverse_symmetry_pixel(sym, P, oa, ob);
    Vec2 q = apply_symmetry({oa + c[0] * kFixed, ob + c[1] * kFixed}, sym, double(P));
    return {clamp_to_unit(q[0] - a), clamp_to_unit(q[1] - b)};
  }

  TableSet tables_;
  PoissonOptions opt_;
};

bool complete(const std::filesystem::path& dir) {
  for (int f = 0; f < kFamilyCount; ++f)
    if (!std::filesystem::exists(dir / table_file_name(Family(f)))) return false;
  return true;
}

}  // namespace

TableSet load_tables(const std::filesystem::path& dir) {
  TableSet set;
  set.dir = dir;
  for (int f = 0; f < kFamilyCount; ++f) {
    Family fam = Family(f);
    set.family[f] = std::make_shared<const SampleTable>(read_table(dir / table_file_name(fam), &fam));
  }
  return set;
}

const TableSet& default_tables() {
  static std::once_flag once;
  static TableSet set;
  std::call_once(once, [] {
    if (const char* env = std::getenv("PDRT_TABLES"); env && *env) {
      set = load_tables(env);
      return;
    }
#ifdef PDRT_BUILD_TABLE_DIR
    if (complete(PDRT_BUILD_TABLE_DIR)) {
      set = load_tables(PDRT_BUILD_TABLE_DIR);
      return;
    }
#endif
    // The cache key names the file format and the generation rule (g2: draws that miss the
    // rho bar are redrawn; g3: balanced 1-D time tables; g4: 2048 of them), so an older pdrt's cache is not reused.
    std::filesystem::path dir = cache_dir() / ("tables-v" + std::to_string(kTableVersion) + "-g4-seed1");
    if (!complete(dir)) {
      std::error_code ec;
      std::filesystem::create_directories(dir, ec);
      if (ec) throw InputError(dir.string() + ": cannot create the table cache (" + ec.message() + ")");
      std::fprintf(stderr, "pdrt: generating the default sample tables into %s (once)\n", dir.c_str());
      for (const TableParams& p : default_table_params()) write_table(dir / table_file_name(p.family), generate_table(p));
    }
    set = load_tables(dir);
  });
  return set;
}

std::unique_ptr<Sampler> make_poisson_sampler(uint64_t seed, const TableSet& tables, PoissonOptions options) {
  return std::make_unique<PoissonSampler>(seed, tables, options);
}

}  // namespace pdrt
