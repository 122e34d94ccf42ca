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

namespace {

constexpr std::size_t kMessageBytes = std::size_t(1) << 30;  // MPI counts are int

// The spans as MPI datatypes of absolute addresses (sent from MPI_BOTTOM), one per message.
std::vector<MPI_Datatype> message_types(const std::vector<ByteSpan>& spans) {
  std::vector<MPI_Datatype> types;
  for (const std::vector<ByteSpan>& message : split_messages(spans, kMessageBytes)) {
    std::vector<int> lengths;
    std::vector<MPI_Aint> addresses;
    for (const ByteSpan& s : message) {
      MPI_Aint a;
      MPI_Get_address(s.data, &a);
      lengths.push_back(int(s.size)), addresses.push_back(a);
    }
    MPI_Datatype t;
    MPI_Type_create_hindexed(int(lengths.size()), lengths.data(), addresses.data(), MPI_BYTE, &t);
    MPI_Type_commit(&t);
    types.push_back(t);
  }
  return types;
}

}  // namespace

void MpiProcessGroup::move_spans(const std::vector<std::vector<ByteSpan>>& send,
                                 const std::vector<std::vector<ByteSpan>>& recv) const {
  std::vector<MPI_Request> requests;
  std::vector<MPI_Datatype> types;
  auto post = [&](const std::vector<std::vector<ByteSpan>>& lists, bool receive) {
    for (int q = 0; q < size_ && q < int(lists.size()); ++q) {
      if (q == rank_) continue;
      const std::vector<MPI_Datatype> t = message_types(lists[std::size_t(q)]);
      for (std::size_t k = 0; k < t.size(); ++k) {
        requests.emplace_back();
        if (receive)
          MPI_Irecv(MPI_BOTTOM, 1, t[k], q, int(k), MPI_COMM_WORLD, &requests.back());
        else
          MPI_Isend(MPI_BOTTOM, 1, t[k], q, int(k), MPI_COMM_WORLD, &requests.back());
      }
      types.insert(types.end(), t.begin(), t.end());
    }
  };
  post(recv, true);
  post(send, false);
  if (std::size_t(rank_) < send.size() && std::size_t(rank_) < recv.size())
    copy_spans(send[std::size_t(rank_)], recv[std::size_t(rank_)]);
  MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  for (MPI_Datatype& t : types) MPI_Type_free(&t);
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
