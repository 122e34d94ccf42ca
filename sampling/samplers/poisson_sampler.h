#pragma once
// `poisson` and `poisson-02`: the samplers that draw per-pixel prototype patterns from the
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

// The default tables, found without user action: $PDRT_TABLES, else the tables the build
// generated, else a per-user cache that is filled (deterministically) on first use.
const TableSet& default_tables(TableSetKind kind = TableSetKind::Poisson);

struct PoissonOptions {
  // A per-stream Cranley–Patterson shift, every family; poisson-02 a digital (xor) shift
  // instead. Off: tests of the bare tables.
  bool toroidal_shift = true;
};

std::unique_ptr<Sampler> make_poisson_sampler(uint64_t seed, const TableSet& tables, PoissonOptions options = {});

}  // namespace pdrt
