#pragma once
// Precomputed hierarchical tables (McCool & Fiume §4–5, Cook §5.1), one file per dimension
// family and table set. Every table is stored in rank order, so every prefix is
// Poisson-disk at its recorded radius. Two sets (issues 16, 28):
//   `poisson`:     2-D families owen-pd (every power-of-two prefix a (0,m,2)-net, scramble
//                  chosen for distance, rho >= 0.35 on every prefix of >= 16 points); time:
//                  stratified-bc (every 2^k prefix one point per 1/2^k stratum).
//   `poisson-065`: 2-D families "(0,2)-first" stratified Poisson-disk (stratified-pd), 2048
//                  points, rho >= 0.65 on every prefix of >= 16 points and >= 0.72 whole;
//                  time: balanced 1-D relaxation at the same bar.
// The pixel family holds one pattern per table spanning a tile of P x P pixels (P = 1 by
// default); each pixel's samples are the points that fall in it, in rank order, stored as
// offsets within the pixel. The format is in docs/table-format.md.
#include "sampling/samplers/sampler.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

inline constexpr uint32_t kTableVersion = 2;

// How a table's points are made: the generator methods of the same names.
enum class Construction : uint8_t { Relaxation = 0, Balanced = 1, StratifiedPD = 2, OwenPD = 3, StratifiedBC = 4 };
inline constexpr int kConstructionCount = 5;
const char* construction_name(Construction c);  // "mccool", "balanced", "stratified-pd", "owen-pd", "stratified-bc"

// The two table sets, read by the samplers of the same names.
enum class TableSetKind : uint8_t { Poisson, Poisson065 };
inline constexpr TableSetKind kTableSets[] = {TableSetKind::Poisson, TableSetKind::Poisson065};
const char* table_set_name(TableSetKind k);  // "poisson", "poisson-065"

struct TableParams {
  Family family = Family::Lens;
  Construction construction = Construction::StratifiedPD;
  uint32_t tables = 16;    // T
  uint32_t points = 2048;  // M per table (non-pixel); samples per pixel wanted (pixel)
  uint32_t tile = 1;       // P (pixel family only)
  uint64_t seed = 1;
  // The bar every table is drawn to (a draw that misses it is redrawn): rho >= prefix_floor
  // on every prefix of >= 16 points, >= whole_floor for the whole set. stratified-pd also
  // places its points by them.
  double prefix_floor = 0.65, whole_floor = 0.72;
  double decay = 0.97, attempts = 30, magnification = 128;  // mccool relaxation
  int candidates = 64;                                      // stratified-pd, stratified-bc
  int depth = 10;                                           // owen-pd: optimised scramble levels
};

struct SampleTable {
  TableParams params;
  int dim = 2;
  uint32_t per_pixel_min = 0;  // pixel family: fewest samples any pixel of any table holds
  // Non-pixel: table t, point i at coords[(t * points + i) * dim + k].
  // Pixel: table t's pixel (a, b) holds cell_count[t][b*P+a] points starting at
  // cell_start[t][b*P+a] (indices into that table's coords, offsets within the pixel).
  std::vector<std::vector<uint32_t>> coords;  // per table, fixed point
  std::vector<std::vector<float>> radius;     // per table, per point (rank order)
  std::vector<std::vector<uint32_t>> cell_start, cell_count;

  uint32_t table_count() const { return uint32_t(coords.size()); }
  std::size_t memory_bytes() const;
};

class Progress;

// Generates a table family; throws UsageError for impossible parameters. `progress`, when
// given, advances by one per finished table.
SampleTable generate_table(const TableParams& params, Progress* progress = nullptr);

void write_table(const std::filesystem::path& path, const SampleTable& table);

// Reads and checks a table file: magic, version, family (when `expected` is given), sizes,
// checksum. Throws InputError naming the file and the problem.
SampleTable read_table(const std::filesystem::path& path, const Family* expected = nullptr);

// The construction a set's tables of `family` must have (load_tables refuses others).
Construction table_set_construction(TableSetKind kind, Family family);
// A table set's parameters per family.
std::vector<TableParams> default_table_params(TableSetKind kind = TableSetKind::Poisson);
std::string table_file_name(Family family, TableSetKind kind = TableSetKind::Poisson);

// The construction's parameters as they are recorded in a table file's header.
std::vector<std::pair<std::string, double>> construction_params(const TableParams& p);

}  // namespace pdrt
