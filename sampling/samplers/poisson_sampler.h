#pragma once
// `poisson` and `poisson-065`: the samplers that draw per-pixel prototype patterns from the
// precomputed hierarchical Poisson-disk tables (Cook §5.1, McCool & Fiume §5.1) of their
// table set (sample_table.h).
#include "sampling/samplers/sample_table.h"
#include "sampling/samplers/sampler.h"

#include <array>
#include <filesystem>
#include <memory>

namespace pdrt {

struct TableSet {
  std::array<std::shared_ptr<const SampleTable>, kFamilyCount> family;
  std::filesystem::path dir;
  TableSetKind kind = TableSetKind::Poisson;
};

// Loads a full table set from `dir` (every family file must be present and valid).
TableSet load_tables(const std::filesystem::path& dir, TableSetKind kind = TableSetKind::Poisson);

// The default tables of `kind` from the cache directory `dir`, generated (deterministically)
// and written there when it lacks them; when it cannot be written, one warning and the
// tables generated in memory.
TableSet cached_tables(const std::filesystem::path& dir, TableSetKind kind);

// The default tables, found without user action: $PDRT_TABLES, else the tables the build
// generated, else a per-user cache that is filled (deterministically) on first use.
const TableSet& default_tables(TableSetKind kind = TableSetKind::Poisson);

// How `poisson` shifts a stream (docs/sampling.md, "Decorrelation"), on top of a symmetry of
// the square: Digital keeps the strata and makes every value uniform, not the distances;
// Toroidal keeps the distances and makes every value uniform, the strata only on the torus;
// Isometric keeps strata and distances (x + 1/2 per axis and a digital shift of the bits below
// kShiftExactBits) but a value is uniform only over quarter cells, which biases smooth
// integrands like a midpoint rule. No shift keeps all three.
enum class PoissonShift : uint8_t { Isometric, Digital, Toroidal };

struct PoissonOptions {
  // Off: tests of the bare tables. `poisson-065` always shifts toroidally.
  bool shift = true;
  // `poisson`: the shift of the lens, light and gloss streams, of the pixel's and of time's.
  // Digital by default: the isometric one's bias shows in renders and tests (docs/sampling.md).
  PoissonShift plane = PoissonShift::Digital, pixel = PoissonShift::Digital, time = PoissonShift::Digital;
  // `poisson-bn` (nonzero): every stream's table, axis swap and digital shift come from a tile
  // of per-pixel keys optimised for blue-noise error on screen at this many samples per pixel
  // (screen_keys.h), under a shift and tile offset per (seed, family, bounce). Needs `poisson`'s
  // untiled, pooled tables.
  int64_t screen_keys_spp = 0;
};

inline constexpr int kShiftExactBits = 12;

std::unique_ptr<Sampler> make_poisson_sampler(uint64_t seed, const TableSet& tables, PoissonOptions options = {});

}  // namespace pdrt
