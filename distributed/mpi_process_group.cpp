#include "distributed/mpi_process_group.h"

#include "sampling/core/errors.h"

#include <mpi.h>

#include <cstdlib>
#include <limits>
#include <string>

namespace pdrt {

bool launched_by_mpi() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK"); }

int launcher_rank() {
  for (const char* v : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK"})
    if (const char* r = std::getenv(v)) return std::atoi(r);
  return 0;
}

namespace {

void finalize_at_exit() {
  int done = 0;
  MPI_Finalized(&done);
  if (!done) MPI_Finalize();
}

}  // namespace

MpiProcessGroup::MpiProcessGroup() {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw InputError("MPI_Init_thread failed");
  std::atexit(finalize_at_exit);
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiProcessGroup& MpiProcessGroup::instance() {
  static MpiProcessGroup group;
  return group;
}

std::vector<std::vector<std::byte>> MpiProcessGroup::all_gather(const std::vector<std::byte>& mine) const {
  // Sizes first, then the bytes; MPI counts are int, so a block over 2 GiB is refused.
  if (mine.size() > size_t(std::numeric_limits<int>::max()))
    throw InputError("rank " + std::to_string(rank_) + ": a block of " + std::to_string(mine.size()) +
                     " bytes exceeds MPI's 2 GiB message limit");
  const int n = int(mine.size());
  std::vector<int> counts(static_cast<size_t>(size_)), displs(static_cast<size_t>(size_));
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  long long total = 0;
  for (int r = 0; r < size_; ++r) {
    if (total > std::numeric_limits<int>::max()) throw InputError("an exchange over 2 GiB exceeds MPI's message limit");
    displs[size_t(r)] = int(total);
    total += counts[size_t(r)];
  }
  std::vector<std::byte> all(static_cast<size_t>(total));
  MPI_Allgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, MPI_COMM_WORLD);
  std::vector<std::vector<std::byte>> out(static_cast<size_t>(size_));
  for (int r = 0; r < size_; ++r)
    out[size_t(r)].assign(all.begin() + displs[size_t(r)], all.begin() + displs[size_t(r)] + counts[size_t(r)]);
  return out;
}

const ProcessGroup& process_group() {
  static const LocalProcessGroup local;
  if (!launched_by_mpi()) return local;
  return MpiProcessGroup::instance();
}

void abort_process_group(int code) {
  int started = 0, done = 0;
  MPI_Initialized(&started);
  MPI_Finalized(&done);
  if (started && !done) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace pdrt
