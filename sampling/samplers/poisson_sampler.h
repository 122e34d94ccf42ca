#pragma once
// `poisson`: the sampler that draws per-pixel prototype patterns from the precomputed
// hierarchical Poisson-disk tables (Cook §5.1, McCool & Fiume §5.1).
#include "sampling/samplers/sample_table.h"
#include "sampling/samplers/sampler.h"

#include <array>
#include <filesystem>
#include <memory>

namespace pdrt {

struct TableSet {
  std::array<std::shared_ptr<const SampleTable>, kFamilyCount> family;
  std::filesystem::path dir;
};

// Loads a full table set from `dir` (every family file must be present and valid).
TableSet load_tables(const std::filesystem::path& dir);

// The default tables, found without user action: $PDRT_TABLES, else the tables the build
// generated, else a per-user cache that is filled (deterministically) on first use.
const TableSet& default_tables();

struct PoissonOptions {
  bool toroidal_shift = true;  // a per-stream Cranley–Patterson shift, every family (off: tests of the bare tables)
};

std::unique_ptr<Sampler> make_poisson_sampler(uint64_t seed, const TableSet& tables, PoissonOptions options = {});

}  // namespace pdrt
