// Generation, serialisation and checking of hierarchical Poisson-disk tables.
#include "sampling/samplers/sample_table.h"

#include "sampling/samplers/sampler.h"

#include "sampling/core/atomic_file.h"
#include "sampling/generators/balanced_relaxation_1d.h"
#include "sampling/core/errors.h"
#include "sampling/core/fixed_point.h"
#include "sampling/core/hash.h"
#include "sampling/core/input_file.h"
#include "sampling/generators/generator.h"
#include "sampling/measures/min_distance.h"
#include "sampling/core/progress.h"
#include "sampling/core/rng.h"
#include "sampling/measures/elementary_intervals.h"
#include "sampling/generators/owen_poisson_2d.h"
#include "sampling/generators/stratified_best_candidate_1d.h"
#include "sampling/generators/stratified_poisson_2d.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace pdrt {
namespace {

constexpr char kMagic[8] = {'P', 'D', 'R', 'T', 'T', 'B', 'L', '1'};
constexpr std::size_t kParamName = 16;  // a construction parameter's name field, NUL padded

PointSet draw_table(const TableParams& p, int dim, int64_t count, uint64_t seed) {
  switch (p.construction) {
    case Construction::Relaxation: {
      if (dim == 1) break;  // 1-D relaxation keeps the radius but not the density: balanced
      GeneratorParams g;
      g.method = "mccool";
      g.dim = dim;
      g.count = count;
      g.periodic = true;  // tables tile: prefixes stay Poisson-disk across pixel/tile borders
      g.seed = seed;
      g.decay = p.decay;
      g.attempts = int64_t(p.attempts);
      g.magnification = p.magnification;
      return generate(g);
    }
    case Construction::Balanced:
      break;
    case Construction::StratifiedPD: {
      StratifiedPoisson2D g;
      g.count = count, g.seed = seed, g.candidates = p.candidates;
      g.prefix_floor = p.prefix_floor, g.whole_floor = p.whole_floor;
      return stratified_poisson_2d(g);
    }
    case Construction::OwenPD: {
      OwenPoisson2D g;
      g.count = count, g.seed = seed, g.depth = p.depth;
      return owen_poisson_2d(g);
    }
    case Construction::StratifiedBC: {
      StratifiedBestCandidate1D g;
      g.count = count, g.seed = seed, g.candidates = p.candidates;
      return stratified_best_candidate_1d(g);
    }
  }
  BalancedRelaxation1D b;
  b.count = count;
  b.seed = seed;
  return balanced_relaxation_1d(b);
}

uint32_t construction_dim(Construction c) {
  return c == Construction::Balanced || c == Construction::StratifiedBC ? 1 : c == Construction::Relaxation ? 0 : 2;
}

// Every table meets its set's bar (issue 3's for `poisson`: rho >= 0.65 for every prefix of
// >= 16 points and >= 0.72 for the whole set). About 1 in 5 balanced 1-D sets ends a little
// under 0.72 (the last points find no gap twice the final radius), so a table that misses
// is redrawn with the next attempt. owen-pd tables must also keep every (0,m,2)-net.
constexpr std::size_t kFirstPrefix = 16;
constexpr int kMaxDraws = 256;

bool meets_quality_bar(const TableParams& p, const PointSet& ps) {
  PointSet q = ps;  // judged as stored: 32-bit fixed point
  for (double& x : q.coords) x = double(to_fixed(x)) * 0x1.0p-32;
  const std::vector<double> rho = prefix_relative_radius(q, true);
  if (rho.empty() || rho.back() < p.whole_floor || worst_prefix_rho(rho, kFirstPrefix) < p.prefix_floor) return false;
  if (p.construction == Construction::OwenPD)
    for (bool net : net_prefixes(q))
      if (!net) return false;
  return true;
}

PointSet relaxation(const TableParams& p, int dim, int64_t count, uint64_t table_index) {
  const uint64_t first_seed = hash_combine(p.seed, (uint64_t(p.family) << 32) | table_index);
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    PointSet ps = draw_table(p, dim, count, draw == 0 ? first_seed : hash_combine(first_seed, uint64_t(draw)));
    if (meets_quality_bar(p, ps)) return ps;
  }
  std::ostringstream msg;
  msg << "tables: " << family_name(p.family) << " table " << table_index << " (" << construction_name(p.construction)
      << ") missed rho >= " << p.prefix_floor << " (prefixes) / " << p.whole_floor << " (whole) in " << kMaxDraws
      << " draws; try other parameters";
  throw InputError(msg.str());
}

// Pixel family: points of one torus pattern grouped by the pixel of the P x P tile they fall
// in, rank order kept inside each pixel, coordinates rewritten as offsets within the pixel.
void bucket_by_pixel(const PointSet& ps, uint32_t P, std::vector<uint32_t>& coords, std::vector<float>& radius,
                     std::vector<uint32_t>& start, std::vector<uint32_t>& count) {
  std::size_t cells = std::size_t(P) * P;
  count.assign(cells, 0);
  std::vector<uint32_t> cell_of(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    auto q = ps.point(i);
    uint32_t a = std::min(uint32_t(q[0] * P), P - 1), b = std::min(uint32_t(q[1] * P), P - 1);
    cell_of[i] = b * P + a;
    ++count[cell_of[i]];
  }
  start.assign(cells, 0);
  for (std::size_t c = 1; c < cells; ++c) start[c] = start[c - 1] + count[c - 1];
  std::vector<uint32_t> fill = start;
  coords.assign(ps.size() * 2, 0);
  radius.assign(ps.size(), 0.0f);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    uint32_t c = cell_of[i], slot = fill[c]++;
    auto q = ps.point(i);
    coords[2 * slot] = to_fixed(q[0] * P - double(c % P));
    coords[2 * slot + 1] = to_fixed(q[1] * P - double(c / P));
    radius[slot] = float(ps.radius[i] * P);  // in pixel units
  }
}

}  // namespace

std::size_t SampleTable::memory_bytes() const {
  std::size_t b = 0;
  for (std::size_t t = 0; t < coords.size(); ++t) b += coords[t].size() * 4 + radius[t].size() * 4;
  for (const auto& v : cell_start) b += v.size() * 4;
  for (const auto& v : cell_count) b += v.size() * 4;
  return b;
}

SampleTable generate_table(const TableParams& p, Progress* progress) {
  if (p.tables < 1 || p.points < 1) throw UsageError("tables: table count and points must be >= 1");
  if (p.family == Family::Pixel && p.tile < 1) throw UsageError("tables: pixel tile must be >= 1");
  const uint32_t cdim = construction_dim(p.construction);
  if (cdim && int(cdim) != family_dim(p.family))
    throw UsageError(std::string("tables: ") + construction_name(p.construction) + " makes " + std::to_string(cdim) +
                     "-D tables; the " + family_name(p.family) + " family is " + std::to_string(family_dim(p.family)) +
                     "-D");
  SampleTable t;
  t.params = p;
  if (p.family != Family::Pixel) t.params.tile = 1;
  t.dim = family_dim(p.family);
  t.coords.resize(p.tables);
  t.radius.resize(p.tables);
  if (p.family == Family::Pixel) {
    t.cell_start.resize(p.tables);
    t.cell_count.resize(p.tables);
  }
  std::vector<uint32_t> min_count(p.tables, 0);
  tbb::parallel_for(uint32_t(0), p.tables, [&](uint32_t k) {
    if (p.family != Family::Pixel) {
      PointSet ps = relaxation(p, t.dim, p.points, k);
      t.coords[k].resize(ps.coords.size());
      for (std::size_t i = 0; i < ps.coords.size(); ++i) t.coords[k][i] = to_fixed(ps.coords[i]);
      t.radius[k].assign(ps.radius.begin(), ps.radius.end());
      if (progress) progress->advance();
      return;
    }
    // Poisson-disk counts per pixel vary only a little; grow the pattern until every pixel
    // of the tile holds the samples wanted.
    // (An untiled table, tile 1, is one pixel: exactly the points wanted.)
    const double pixels = double(p.tile) * p.tile;
    double total = p.tile == 1 ? double(p.points) : pixels * p.points * 1.05 + 16;
    for (;;) {
      PointSet ps = relaxation(p, 2, int64_t(total), k);
      bucket_by_pixel(ps, p.tile, t.coords[k], t.radius[k], t.cell_start[k], t.cell_count[k]);
      min_count[k] = *std::min_element(t.cell_count[k].begin(), t.cell_count[k].end());
      if (min_count[k] >= p.points) break;
      total *= 1.05;
    }
    if (progress) progress->advance();
  });
  t.per_pixel_min = p.family == Family::Pixel ? *std::min_element(min_count.begin(), min_count.end()) : p.points;
  return t;
}

// ---- Serialisation ---------------------------------------------------------------------

namespace {

template <class T>
void put(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

template <class T>
void put_vec(std::string& out, const std::vector<T>& v) {
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

class Reader {
 public:
  Reader(const std::string& data, std::string name) : d_(data), name_(std::move(name)) {}
  template <class T>
  T get(const char* what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, d_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return v;
  }
  template <class T>
  void get_vec(std::vector<T>& v, std::size_t n, const char* what) {
    need(n * sizeof(T), what);
    v.resize(n);
    if (n) std::memcpy(v.data(), d_.data() + pos_, n * sizeof(T));  // an empty vector's data() may be null
    pos_ += n * sizeof(T);
  }
  std::size_t pos() const { return pos_; }
  [[noreturn]] void fail(const std::string& msg) const { throw InputError(name_ + ": " + msg); }

 private:
  void need(std::size_t n, const char* what) const {
    if (n > d_.size() - pos_) fail(std::string("truncated: file ends inside ") + what);
  }
  const std::string& d_;
  std::string name_;
  std::size_t pos_ = 0;
};

}  // namespace

void write_table(const std::filesystem::path& path, const SampleTable& t) {
  std::string out;
  out.append(kMagic, sizeof kMagic);
  put<uint32_t>(out, kTableVersion);
  put<uint8_t>(out, uint8_t(t.params.family));
  put<uint8_t>(out, uint8_t(t.dim));
  put<uint8_t>(out, uint8_t(t.params.construction));
  put<uint8_t>(out, 0);
  put<uint32_t>(out, t.table_count());
  put<uint32_t>(out, t.params.points);
  put<uint32_t>(out, t.params.tile);
  put<uint32_t>(out, t.per_pixel_min);
  put<uint64_t>(out, t.params.seed);
  const auto named = construction_params(t.params);
  put<uint32_t>(out, uint32_t(named.size()));
  for (const auto& [name, value] : named) {
    char field[kParamName] = {};
    std::memcpy(field, name.data(), std::min(name.size(), kParamName - 1));
    out.append(field, kParamName);
    put<double>(out, value);
  }
  for (uint32_t k = 0; k < t.table_count(); ++k) {
    put<uint32_t>(out, uint32_t(t.radius[k].size()));
    if (t.params.family == Family::Pixel) {
      put_vec(out, t.cell_start[k]);
      put_vec(out, t.cell_count[k]);
    }
    put_vec(out, t.coords[k]);
    put_vec(out, t.radius[k]);
  }
  put<uint64_t>(out, fnv1a(std::string_view(out.data(), out.size())));
  write_file_atomically(path, [&](std::ostream& os) { os.write(out.data(), std::streamsize(out.size())); });
}

SampleTable read_table(const std::filesystem::path& path, const Family* expected) {
  const std::string name = path.string();
  std::ifstream in = open_for_reading(path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string data = ss.str();
  Reader r(data, name);
  char magic[8];
  for (char& c : magic) c = r.get<char>("the magic number");
  if (std::memcmp(magic, kMagic, 8) != 0) r.fail("not a pdrt sample table (bad magic number)");
  uint32_t version = r.get<uint32_t>("the header");
  if (version != kTableVersion)
    r.fail("table format version " + std::to_string(version) + ", this pdrt reads version " +
           std::to_string(kTableVersion) + "; regenerate with `pdrt tables`");
  SampleTable t;
  uint8_t family = r.get<uint8_t>("the header");
  if (family >= kFamilyCount) r.fail("unknown family " + std::to_string(family));
  t.params.family = Family(family);
  if (expected && *expected != t.params.family)
    r.fail(std::string("holds the ") + family_name(t.params.family) + " family, expected " + family_name(*expected));
  t.dim = r.get<uint8_t>("the header");
  if (t.dim != family_dim(t.params.family)) r.fail("dimension " + std::to_string(t.dim) + " does not match its family");
  const uint8_t construction = r.get<uint8_t>("the header");
  if (construction >= kConstructionCount) r.fail("unknown construction " + std::to_string(construction));
  t.params.construction = Construction(construction);
  r.get<uint8_t>("the header");
  uint32_t tables = r.get<uint32_t>("the header");
  t.params.tables = tables;
  t.params.points = r.get<uint32_t>("the header");
  t.params.tile = r.get<uint32_t>("the header");
  t.per_pixel_min = r.get<uint32_t>("the header");
  t.params.seed = r.get<uint64_t>("the header");
  const uint32_t named = r.get<uint32_t>("the header");
  if (named > 64) r.fail("header says " + std::to_string(named) + " construction parameters, at most 64");
  for (uint32_t i = 0; i < named; ++i) {
    char field[kParamName];
    for (char& c : field) c = r.get<char>("the construction parameters");
    const std::string name(field, strnlen(field, kParamName));
    const double v = r.get<double>("the construction parameters");
    if (!std::isfinite(v)) r.fail("construction parameter " + name + " is not finite");
    if (name == "prefix_floor")
      t.params.prefix_floor = v;
    else if (name == "whole_floor")
      t.params.whole_floor = v;
    else if (name == "decay")
      t.params.decay = v;
    else if (name == "attempts")
      t.params.attempts = v;
    else if (name == "magnification")
      t.params.magnification = v;
    else if (name == "candidates")
      t.params.candidates = int(std::clamp(v, 0.0, 1e9));
    else if (name == "depth")
      t.params.depth = int(std::clamp(v, 0.0, 64.0));
    else
      r.fail("unknown construction parameter '" + name + "' for " + construction_name(t.params.construction));
  }
  const bool pixel = t.params.family == Family::Pixel;
  // Each header field on its own, before the checksum, so a damaged header says which field is wrong.
  if (tables == 0) r.fail("header field tables is 0");
  if (!pixel && t.params.points == 0) r.fail("header field points is 0");
  if (t.params.tile == 0 || (pixel && t.params.tile > 4096) || (!pixel && t.params.tile != 1))
    r.fail("header field tile is " + std::to_string(t.params.tile) + ", expected " +
           (pixel ? "1 to 4096 for the pixel family" : "1 for this family"));
  const std::size_t cells = std::size_t(t.params.tile) * t.params.tile;
  // The smallest file the header allows: per table its count, then the pixel index, or
  // `points` coordinates and radii (pixel tables hold a variable count).
  const double per_table = 4.0 + (pixel ? 8.0 * double(cells) : double(t.params.points) * (4.0 * t.dim + 4.0));
  const double least = double(r.pos()) + double(tables) * per_table + 8.0;
  if (least > double(data.size())) {
    char needed[40];  // 2^32 tables of 2^32 points: more bytes than a uint64_t counts
    std::snprintf(needed, sizeof needed, "%.0f", least);
    r.fail("header says " + std::to_string(tables) + " tables" +
           (pixel ? " of " + std::to_string(t.params.tile) + "x" + std::to_string(t.params.tile) + " pixels"
                  : " of " + std::to_string(t.params.points) + " points") +
           ", which needs at least " + needed + " bytes; the file has " + std::to_string(data.size()) +
           " (header field tables or points is wrong, or the file is truncated)");
  }
  uint64_t stored;
  std::memcpy(&stored, data.data() + data.size() - 8, 8);
  if (fnv1a(std::string_view(data).substr(0, data.size() - 8)) != stored)
    r.fail("checksum mismatch: the file is truncated or corrupted");
  t.coords.resize(tables);
  t.radius.resize(tables);
  if (pixel) t.cell_start.resize(tables), t.cell_count.resize(tables);
  for (uint32_t k = 0; k < tables; ++k) {
    uint32_t n = r.get<uint32_t>("a table header");
    if (pixel) {
      r.get_vec(t.cell_start[k], cells, "a pixel index");
      r.get_vec(t.cell_count[k], cells, "a pixel index");
      uint64_t sum = 0;
      for (std::size_t c = 0; c < cells; ++c) {
        if (t.cell_start[k][c] != sum) r.fail("pixel index of table " + std::to_string(k) + " is inconsistent");
        if (t.cell_count[k][c] == 0)
          r.fail("pixel " + std::to_string(c % t.params.tile) + "," + std::to_string(c / t.params.tile) + " of table " +
                 std::to_string(k) + " holds no points");
        sum += t.cell_count[k][c];
      }
      if (sum != n) r.fail("pixel index of table " + std::to_string(k) + " does not cover its points");
    } else if (n != t.params.points) {
      r.fail("table " + std::to_string(k) + " has " + std::to_string(n) + " points, header says " +
             std::to_string(t.params.points));
    }
    r.get_vec(t.coords[k], std::size_t(n) * t.dim, "coordinates");
    r.get_vec(t.radius[k], n, "radii");
  }
  if (r.pos() != data.size() - 8) r.fail("trailing bytes after the last table");
  if (pixel) {
    // Reports quote per_pixel_min; a header that contradicts its own pixel index is damaged.
    uint32_t fewest = UINT32_MAX;
    for (const auto& counts : t.cell_count)
      for (uint32_t c : counts) fewest = std::min(fewest, c);
    if (t.per_pixel_min != fewest)
      r.fail("header field per_pixel_min is " + std::to_string(t.per_pixel_min) + ", the fewest points of a pixel is " +
             std::to_string(fewest));
  }
  return t;
}

const char* construction_name(Construction c) {
  static const char* const names[] = {"mccool", "balanced", "stratified-pd", "owen-pd", "stratified-bc"};
  return names[int(c) < kConstructionCount ? int(c) : 0];
}

// A table set is named after the sampler that reads it.
const char* table_set_name(TableSetKind k) {
  return sampler_name(k == TableSetKind::Poisson065 ? SamplerKind::Poisson065 : SamplerKind::Poisson);
}

Construction table_set_construction(TableSetKind kind, Family family) {
  if (kind == TableSetKind::Poisson065)
    return family == Family::Time ? Construction::Balanced : Construction::StratifiedPD;
  return family == Family::Time ? Construction::StratifiedBC : Construction::OwenPD;
}

std::vector<std::pair<std::string, double>> construction_params(const TableParams& p) {
  std::vector<std::pair<std::string, double>> v = {{"prefix_floor", p.prefix_floor}, {"whole_floor", p.whole_floor}};
  switch (p.construction) {
    case Construction::Relaxation:
      v.insert(v.end(), {{"decay", p.decay}, {"attempts", p.attempts}, {"magnification", p.magnification}});
      break;
    case Construction::StratifiedPD:
    case Construction::StratifiedBC:
      v.push_back({"candidates", p.candidates});
      break;
    case Construction::OwenPD:
      v.push_back({"depth", p.depth});
      break;
    case Construction::Balanced:
      break;
  }
  return v;
}

std::vector<TableParams> default_table_params(TableSetKind kind) {
  // See docs/sampling.md for the reasoning behind these sizes.
  std::vector<TableParams> v;
  for (Family f : {Family::Pixel, Family::Lens, Family::Time, Family::Light, Family::Gloss}) {
    TableParams p;
    p.family = f;
    // Enough tables that the streams of one path at max_depth 16 take distinct ones (the
    // sampler allocates them without replacement): time carries the shutter and three
    // decisions per vertex (49 salts), light and gloss one per vertex (16). The pixel family
    // is untiled (tile 1): each pixel's pattern is a shifted table of its own, so every
    // sample index is uniform in the pixel over seeds (a window of a tiled pattern pulls its
    // first points toward the window's centre).
    p.tables = f == Family::Time ? 64 : 16;
    // 2048 points, twice the samples a pixel uses, so 1024 spp reads a prefix, which is more
    // even than a whole table (its last points must saturate the gaps for the rho bar).
    p.points = 2048;
    p.construction = table_set_construction(kind, f);
    if (kind == TableSetKind::Poisson) {
      // Strict strata: the bar is what a (0,2)-sequence can reach (stratified-pd.md: 0.41
      // at best over every prefix), and 1-D progressive jitter with best candidates.
      p.points = f == Family::Time ? 2048 : 1024;
      p.prefix_floor = f == Family::Time ? 0.25 : 0.35;
      p.whole_floor = 0.0;
      p.candidates = 16;
    }
    v.push_back(p);
  }
  return v;
}

std::string table_file_name(Family family, TableSetKind kind) {
  return std::string(family_name(family)) + (kind == TableSetKind::Poisson065 ? ".065" : "") + ".pdrttbl";
}

}  // namespace pdrt
