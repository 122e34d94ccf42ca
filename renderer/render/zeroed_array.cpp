#include "renderer/render/zeroed_array.h"

#include <sys/mman.h>

#include <cstdlib>
#include <new>

namespace pdrt {

namespace {
constexpr std::size_t kMapFrom = std::size_t(64) << 10;  // smaller arrays come from calloc
}  // namespace

ZeroedBytes::ZeroedBytes(std::size_t bytes) : bytes_(bytes) {
  if (bytes == 0) return;
  if (bytes >= kMapFrom) {
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
  if (mapped_)
    munmap(p_, bytes_);
  else
    std::free(p_);
  p_ = nullptr;
}

}  // namespace pdrt
