#pragma once
// The processes a render is shared among (docs/distributed.md). The renderer knows only this
// interface: one process by default, MPI ranks under `mpirun` (distributed/mpi_process_group.h).
// Ranks render fixed blocks and exchange their bytes; nothing is ever reduced in floating
// point across processes, so the image does not depend on how many there are.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pdrt {

class ProcessGroup {
 public:
  virtual ~ProcessGroup() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Every process's `mine`, indexed by rank, on every process. Collective: every process calls
  // it the same number of times, in the same order.
  virtual std::vector<std::vector<std::byte>> all_gather(const std::vector<std::byte>& mine) const = 0;
};

// The single process pdrt is without mpirun.
class LocalProcessGroup final : public ProcessGroup {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<std::vector<std::byte>> all_gather(const std::vector<std::byte>& mine) const override { return {mine}; }
};

}  // namespace pdrt
