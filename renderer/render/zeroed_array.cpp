#include "renderer/render/zeroed_array.h"

#include <sys/mman.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>
#include <utility>

namespace pdrt {

namespace {
constexpr std::size_t kMapFrom = std::size_t(64) << 10;  // smaller arrays come from calloc
constexpr std::size_t kKeepUpTo = std::size_t(64) << 20;

struct Mapping {
  void* p = nullptr;
  std::size_t bytes = 0;
};

// The last two released mappings of at most kKeepUpTo bytes each, kept for the next arrays
// of their size: compare, the benchmarks and a plan's jobs render many images of one size in
// a process (a split render makes two films), and a page's first touch is a page fault (13 us
// in the sandboxed virtual machines CI runs on, where a 320 x 240 film's 4,200 faults took
// 55 ms against 0.4-1.2 ms to zero the pages again). Larger films are left to the kernel:
// zeroing them would map the pages of every tile on an MPI rank that renders a few.
class KeptMappings {
 public:
  void* take(std::size_t bytes) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (Mapping& m : kept_)
      if (m.p && m.bytes == bytes) return std::exchange(m.p, nullptr);
    return nullptr;
  }
  // Keeps p, or returns the mapping the caller must unmap (p itself, or the oldest kept when
  // no slot is free).
  Mapping keep(void* p, std::size_t bytes) {
    if (bytes > kKeepUpTo) return {p, bytes};
    std::lock_guard<std::mutex> lock(mutex_);
    auto out = std::find_if(kept_.begin(), kept_.end(), [](const Mapping& m) { return !m.p; });
    if (out == kept_.end()) --out;
    const Mapping old = *out;
    std::move_backward(kept_.begin(), out, out + 1);
    kept_.front() = {p, bytes};
    return old;
  }

 private:
  std::mutex mutex_;
  std::array<Mapping, 2> kept_{};  // newest first
};

KeptMappings& kept_mappings() {
  static KeptMappings* k = new KeptMappings;  // never destroyed: arrays may outlive static destruction
  return *k;
}
}  // namespace

ZeroedBytes::ZeroedBytes(std::size_t bytes) : bytes_(bytes) {
  if (bytes == 0) return;
  if (bytes >= kMapFrom) {
    if (void* p = kept_mappings().take(bytes)) {
      std::memset(p, 0, bytes);
      p_ = p, mapped_ = true;
      return;
    }
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    // Ordinary pages even where the kernel would make huge ones of every mapping: a rank maps
    // its tiles' pages, not 2 MiB around each, and a 1080p film's system time rose from 0.45 to
    // 0.93-1.28 s with huge pages (the kernel's compaction; docs/renderer.md, "Film"). Advice only.
    madvise(p, bytes, MADV_NOHUGEPAGE);
    p_ = p, mapped_ = true;
  } else {
    p_ = std::calloc(1, bytes);
    if (!p_) throw std::bad_alloc();
  }
}

ZeroedBytes::~ZeroedBytes() { release(); }

ZeroedBytes::ZeroedBytes(const ZeroedBytes& o) : ZeroedBytes(o.bytes_) {
  if (bytes_) std::memcpy(p_, o.p_, bytes_);
}

ZeroedBytes& ZeroedBytes::operator=(const ZeroedBytes& o) {
  if (this != &o) *this = ZeroedBytes(o);
  return *this;
}

ZeroedBytes& ZeroedBytes::operator=(ZeroedBytes&& o) noexcept {
  if (this != &o) {
    release();
    p_ = o.p_, bytes_ = o.bytes_, mapped_ = o.mapped_;
    o.p_ = nullptr, o.bytes_ = 0;
  }
  return *this;
}

void ZeroedBytes::release() {
  if (!p_) return;
  if (mapped_) {
    const Mapping old = kept_mappings().keep(p_, bytes_);
    if (old.p) munmap(old.p, old.bytes);
  } else
    std::free(p_);
  p_ = nullptr;
}

}  // namespace pdrt
