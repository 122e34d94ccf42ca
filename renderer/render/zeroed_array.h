#pragma once
// An array whose elements start as all-zero bytes, on pages the kernel zeroes when they are
// first touched (anonymous mmap from 64 KiB on, without huge pages; calloc below): allocating a film costs no
// time, the threads that render a tile fault in its pages in parallel, and an MPI rank maps
// only the pages of the tiles it renders (filling a 1080p film, 464 MB, on one thread takes
// about 0.2 s, before any pass could start). The last two released mappings of up to 64 MiB
// are kept and zeroed again for the next arrays of their size: a process that renders many
// images (compare, the benchmarks) then pays their page faults once. T must be trivially copyable and
// destructible, and its all-zero bytes must be the value it is meant to start with.
#include <cstddef>
#include <cstring>
#include <type_traits>

namespace pdrt {

class ZeroedBytes {
 public:
  ZeroedBytes() = default;
  explicit ZeroedBytes(std::size_t bytes);
  ~ZeroedBytes();
  ZeroedBytes(const ZeroedBytes& o);
  ZeroedBytes& operator=(const ZeroedBytes& o);
  ZeroedBytes(ZeroedBytes&& o) noexcept : p_(o.p_), bytes_(o.bytes_), mapped_(o.mapped_) {
    o.p_ = nullptr, o.bytes_ = 0;
  }
  ZeroedBytes& operator=(ZeroedBytes&& o) noexcept;
  void* data() const { return p_; }
  std::size_t size() const { return bytes_; }

 private:
  void release();
  void* p_ = nullptr;
  std::size_t bytes_ = 0;
  bool mapped_ = false;
};

template <class T>
class ZeroedArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  ZeroedArray() = default;
  explicit ZeroedArray(std::size_t n) : bytes_(n * sizeof(T)), n_(n) {}
  T& operator[](std::size_t i) { return data()[i]; }
  const T& operator[](std::size_t i) const { return data()[i]; }
  T* data() { return static_cast<T*>(bytes_.data()); }
  const T* data() const { return static_cast<const T*>(bytes_.data()); }
  std::size_t size() const { return n_; }

 private:
  ZeroedBytes bytes_;
  std::size_t n_ = 0;
};

}  // namespace pdrt
