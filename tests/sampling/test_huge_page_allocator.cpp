#include "sampling/core/huge_page_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace pdrt {
namespace {

TEST(HugePageAllocator, LargeBlocksStartOnATwoMebibyteBoundary) {
  HugePageAllocator<double> a;
  const std::size_t n = (std::size_t(5) << 20) / sizeof(double);  // 5 MiB
  double* p = a.allocate(n);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % (std::size_t(2) << 20), 0u);
  a.deallocate(p, n);
}

TEST(HugePageAllocator, VectorsSmallAndLargeKeepTheirValuesThroughGrowth) {
  // Growth moves the elements between a small block (operator new) and large ones
  // (aligned_alloc), and frees each with its own counterpart.
  std::vector<uint32_t, HugePageAllocator<uint32_t>> v;
  for (uint32_t i = 0; i < (3u << 20); ++i) v.push_back(i * 2654435761u);
  ASSERT_EQ(v.size(), 3u << 20);
  for (uint32_t i = 0; i < v.size(); i += 4099) ASSERT_EQ(v[i], i * 2654435761u) << i;
  v.resize(10);
  v.shrink_to_fit();
  EXPECT_EQ(v[9], 9u * 2654435761u);
}

}  // namespace
}  // namespace pdrt
