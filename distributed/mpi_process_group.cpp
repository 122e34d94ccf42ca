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

namespace {

// MPI counts are int, so a block or an exchange over 2 GiB is refused.
int block_size(const std::vector<std::byte>& mine, int rank) {
  if (mine.size() > size_t(std::numeric_limits<int>::max()))
    throw InputError("rank " + std::to_string(rank) + ": a block of " + std::to_string(mine.size()) +
                     " bytes exceeds MPI's 2 GiB message limit");
  return int(mine.size());
}

// Displacements of the blocks of `counts` in one buffer; the buffer's size.
size_t displacements(const std::vector<int>& counts, std::vector<int>* displs) {
  long long total = 0;
  displs->assign(counts.size(), 0);
  for (size_t r = 0; r < counts.size(); ++r) {
    if (total > std::numeric_limits<int>::max()) throw InputError("an exchange over 2 GiB exceeds MPI's message limit");
    (*displs)[r] = int(total);
    total += counts[r];
  }
  return size_t(total);
}

std::vector<std::vector<std::byte>> split(const std::vector<std::byte>& all, const std::vector<int>& counts,
                                          const std::vector<int>& displs) {
  std::vector<std::vector<std::byte>> out(counts.size());
  for (size_t r = 0; r < counts.size(); ++r)
    out[r].assign(all.begin() + displs[r], all.begin() + displs[r] + counts[r]);
  return out;
}

}  // namespace

// Sizes first, then the bytes.
std::vector<std::vector<std::byte>> MpiProcessGroup::all_gather(const std::vector<std::byte>& mine) const {
  const int n = block_size(mine, rank_);
  std::vector<int> counts(static_cast<size_t>(size_)), displs;
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::vector<std::byte> all(displacements(counts, &displs));
  MPI_Allgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, MPI_COMM_WORLD);
  return split(all, counts, displs);
}

GatheredBytes MpiProcessGroup::gather_to_lead(const std::vector<std::byte>& mine) const {
  const int n = block_size(mine, rank_);
  const bool lead = rank_ == 0;
  std::vector<int> counts(lead ? static_cast<size_t>(size_) : 0), displs;
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  GatheredBytes out;
  if (lead) {
    out.bytes.resize(displacements(counts, &displs));
    out.begin.assign(displs.begin(), displs.end());
    out.begin.push_back(out.bytes.size());
  }
  MPI_Gatherv(mine.data(), n, MPI_BYTE, out.bytes.data(), counts.data(), displs.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
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
