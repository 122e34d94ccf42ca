#pragma once
// The processes a render is shared among (docs/distributed.md). The renderer knows only this
// interface: one process by default, MPI ranks under `mpirun` (distributed/mpi_process_group.h).
// Ranks render fixed blocks and exchange their bytes; nothing is ever reduced in floating
// point across processes, so the image does not depend on how many there are.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pdrt {

// A run of bytes a process sends from or receives into where they lie (a film's rows).
struct ByteSpan {
  std::byte* data;
  std::size_t size;
};

// Copies the bytes of `from`, in order, into `to` (the same total).
void copy_spans(const std::vector<ByteSpan>& from, const std::vector<ByteSpan>& to);
// The spans cut into messages of `limit` bytes each (the last one shorter): message k holds
// bytes [k limit, (k + 1) limit) of the list, so two lists of the same total cut alike
// whatever their spans.
std::vector<std::vector<ByteSpan>> split_messages(const std::vector<ByteSpan>& spans, std::size_t limit);

class ProcessGroup {
 public:
  virtual ~ProcessGroup() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Every process's `mine`, indexed by rank, on every process. Collective: every process calls
  // it the same number of times, in the same order.
  virtual std::vector<std::vector<std::byte>> all_gather(const std::vector<std::byte>& mine) const = 0;
  // Moves bytes where they lie, without staging buffers: process p's send[q] (indexed by rank;
  // empty: nothing for q) lands, in order, in process q's recv[p], which holds as many bytes.
  // A film's share is hundreds of MB at 1080p, and a buffer that size costs more in page
  // faults than the transfer itself (docs/distributed.md). Collective, like all_gather.
  virtual void move_spans(const std::vector<std::vector<ByteSpan>>& send,
                          const std::vector<std::vector<ByteSpan>>& recv) const = 0;
};

// The single process pdrt is without mpirun.
class LocalProcessGroup final : public ProcessGroup {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<std::vector<std::byte>> all_gather(const std::vector<std::byte>& mine) const override { return {mine}; }
  void move_spans(const std::vector<std::vector<ByteSpan>>& send,
                  const std::vector<std::vector<ByteSpan>>& recv) const override {
    if (!send.empty() && !recv.empty()) copy_spans(send[0], recv[0]);
  }
};

}  // namespace pdrt
