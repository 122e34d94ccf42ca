#pragma once
// Precomputed hierarchical Poisson-disk tables (McCool & Fiume §4–5, Cook §5.1), one file per
// dimension family. Every table is a McCool–Fiume relaxation set on the torus, stored in rank
// order, so every prefix is Poisson-disk at its recorded radius.
//
// The pixel family (McCool §5.1) holds one periodic pattern per table spanning a tile of
// P x P pixels; each pixel's samples are the points that fall in it, in rank order, stored as
// offsets within the pixel. The other families hold T tables of M points each.
//
// File format (little-endian, documented in docs/table-format.md):
//   magic "PDRTTBL1", u32 version, u8 family, u8 dim, u16 reserved, u32 tables, u32 points,
//   u32 tile (P, 1 for non-pixel families), u32 per_pixel_min, u64 seed, f64 decay,
//   f64 attempts, f64 magnification, then per table: for pixel tables P*P u32 counts and
//   offsets; coordinates as u32 fixed point (x * 2^32), f32 radius per point; finally a
//   u64 FNV-1a checksum of everything before it.
#include "sampling/samplers/sampler.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

inline constexpr uint32_t kTableVersion = 1;

struct TableParams {
  Family family = Family::Lens;
  uint32_t tables = 16;        // T
  uint32_t points = 1024;      // M per table (non-pixel); samples per pixel wanted (pixel)
  uint32_t tile = 1;           // P (pixel family only)
  uint64_t seed = 1;
  double decay = 0.97, attempts = 30, magnification = 128;  // McCool–Fiume relaxation
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

// The default table set: parameters per family.
std::vector<TableParams> default_table_params();
std::string table_file_name(Family family);

}  // namespace pdrt
