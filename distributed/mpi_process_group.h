#pragma once
// MPI ranks as pdrt's ProcessGroup (renderer/render/process_group.h). pdrt initialises MPI
// only when `mpirun` started it (the launcher's environment says so), so a plain `pdrt render`
// starts no MPI runtime and behaves as a single process.
#include "renderer/render/process_group.h"

#include <memory>

namespace pdrt {

// True when this process was started by an MPI launcher (Open MPI's OMPI_COMM_WORLD_SIZE or
// PMIx's PMIX_RANK in the environment).
bool launched_by_mpi();

// This process's rank as the launcher's environment gives it (0 without a launcher), known
// before MPI starts: only rank 0 speaks, so errors found while checking the input print once.
int launcher_rank();

// Initialises MPI (thread level FUNNELED: only the main thread calls MPI) on first use and
// finalises it at exit. Errors abort the whole job (MPI_ERRORS_ARE_FATAL): a rank that fails
// takes the others down instead of leaving them waiting.
class MpiProcessGroup final : public ProcessGroup {
 public:
  static MpiProcessGroup& instance();
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  std::vector<std::vector<std::byte>> all_gather(const std::vector<std::byte>& mine) const override;
  // Point to point, each list sent as MPI datatypes of its spans' addresses (MPI_BOTTOM), in
  // messages of at most 1 GiB (MPI counts are int).
  void move_spans(const std::vector<std::vector<ByteSpan>>& send,
                  const std::vector<std::vector<ByteSpan>>& recv) const override;

 private:
  MpiProcessGroup();
  int rank_ = 0, size_ = 1;
};

// The group this process belongs to: MPI's under mpirun, else the single local process.
const ProcessGroup& process_group();

// Ends every process of the group with `code`: a rank that fails alone must not leave the
// others waiting in their next exchange (MPI_Abort when MPI runs, else exit).
[[noreturn]] void abort_process_group(int code);

}  // namespace pdrt
