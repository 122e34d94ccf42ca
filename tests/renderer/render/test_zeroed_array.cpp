// ZeroedArray (renderer/render/zeroed_array.h): every array starts all zero, also one made on
// the mapping of a released one (compare renders many films of one size in a process).
#include "renderer/render/zeroed_array.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

using namespace pdrt;

namespace {
constexpr std::size_t kBytes = std::size_t(3) << 20;  // mapped (from 64 KiB), and kept (up to 64 MiB)

bool all_zero(const ZeroedArray<uint8_t>& a) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != 0) return false;
  return true;
}
}  // namespace

TEST(ZeroedArray, AnArrayOnAReleasedArraysMappingStartsAllZero) {
  const void* released = nullptr;
  {
    ZeroedArray<uint8_t> a(kBytes);
    std::memset(a.data(), 0xab, kBytes);
    released = a.data();
  }
  ZeroedArray<uint8_t> b(kBytes);
  EXPECT_EQ(static_cast<const void*>(b.data()), released) << "the released mapping was not reused";
  EXPECT_TRUE(all_zero(b));
}

TEST(ZeroedArray, TwoLiveArraysOfOneSizeNeverShareAMapping) {
  { ZeroedArray<uint8_t> gone(kBytes); }
  ZeroedArray<uint8_t> a(kBytes), b(kBytes);
  EXPECT_NE(a.data(), b.data());
  std::memset(a.data(), 1, kBytes);
  EXPECT_TRUE(all_zero(b));
}

// A split render's two films are both kept, also after one of them was taken and released
// again (the released one fills the free place instead of pushing the other out).
TEST(ZeroedArray, TheLastTwoReleasedMappingsAreKept) {
  auto a = std::make_unique<ZeroedArray<uint8_t>>(kBytes), b = std::make_unique<ZeroedArray<uint8_t>>(kBytes);
  const void* mapped[2] = {a->data(), b->data()};
  a.reset(), b.reset();
  { ZeroedArray<uint8_t> again(kBytes); }
  ZeroedArray<uint8_t> c(kBytes), d(kBytes);
  for (const void* p : {static_cast<const void*>(c.data()), static_cast<const void*>(d.data())})
    EXPECT_TRUE(p == mapped[0] || p == mapped[1]) << "a kept mapping was unmapped";
  EXPECT_TRUE(all_zero(c) && all_zero(d));
}

// An array above 64 MiB is unmapped when released: the next one's pages are not resident
// until touched (an MPI rank maps only its own tiles of a large film).
TEST(ZeroedArray, ALargeArraysMappingIsNotKept) {
  const std::size_t big = std::size_t(65) << 20;
  const long page = sysconf(_SC_PAGESIZE);
  {
    ZeroedArray<uint8_t> a(big);
    std::memset(a.data(), 1, std::size_t(page) * 4);
  }
  ZeroedArray<uint8_t> b(big);
  std::vector<unsigned char> v(4);
  ASSERT_EQ(mincore(b.data(), std::size_t(page) * 4, v.data()), 0);
  for (unsigned char c : v) EXPECT_EQ(c & 1, 0);
}
