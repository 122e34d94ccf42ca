// Film accumulation (renderer/render/film.h): what a pixel keeps of its samples.
#include "renderer/render/film.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

using namespace pdrt;

// A NaN or infinite sample is dropped with no weight and counted: the pixel keeps the mean of
// its finite samples instead of being pulled toward black by a zero at full filter weight.
TEST(Film, NonFiniteSamplesAreDroppedWithoutWeightAndCounted) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (Vec3 bad : {Vec3(nan, 0.5f, 0.5f), Vec3(0.5f, inf, 0.5f), Vec3(0.5f, 0.5f, -inf)}) {
    PixelAccum acc;
    acc.add(Vec3(0.5f), 1.0f, Vec3(1.0f), Vec3(0, 0, 1), 2.0f, 0);
    acc.add(bad, 1.0f, Vec3(1.0f), Vec3(0, 0, 1), 2.0f, 1);
    acc.add(Vec3(0.7f), 0.5f, Vec3(1.0f), Vec3(0, 0, 1), 2.0f, 0);
    const Vec3 v = acc.value();
    const float expected = (0.5f * 1.0f + 0.7f * 0.5f) / 1.5f;
    EXPECT_FLOAT_EQ(v.x, expected);
    EXPECT_FLOAT_EQ(v.y, expected);
    EXPECT_FLOAT_EQ(v.z, expected);
    EXPECT_EQ(acc.samples, 2);
    EXPECT_EQ(acc.dropped, 1);
    EXPECT_DOUBLE_EQ(acc.w, 1.5);
    EXPECT_TRUE(std::isfinite(acc.variance_of_mean()));
  }
}

// A film starts as zero bytes on pages the kernel zeroes (zeroed_array.h), so PixelAccum{} must
// be all zero bytes: a member whose default is not zero would start as zero in every film.
TEST(Film, AnEmptyPixelIsAllZeroBytes) {
  const PixelAccum p{};
  const unsigned char* b = reinterpret_cast<const unsigned char*>(&p);
  for (std::size_t i = 0; i < sizeof p; ++i) ASSERT_EQ(b[i], 0) << "byte " << i;
  Film film(40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) ASSERT_EQ(std::memcmp(&film.at(x, y), &p, sizeof p), 0);
}

// The per-channel range starts at the first sample (it has no sentinel), however large.
TEST(Film, ContrastSpansTheSamplesFromTheFirst) {
  PixelAccum acc;
  EXPECT_TRUE(std::isinf(acc.contrast(0)));  // fewer than two samples: unknown
  acc.add(Vec3(5.0f, 2e30f, 0.25f), 1.0f, Vec3(1.0f), Vec3(0, 0, 1), 1.0f, 0);
  acc.add(Vec3(3.0f, 1e30f, 0.25f), 1.0f, Vec3(1.0f), Vec3(0, 0, 1), 1.0f, 1);
  EXPECT_DOUBLE_EQ(acc.contrast(0), (5.0 - 3.0) / (5.0 + 3.0));
  EXPECT_NEAR(acc.contrast(1), 1.0 / 3.0, 1e-7);
  EXPECT_DOUBLE_EQ(acc.contrast(2), 0.0);
  acc.add(Vec3(-1.0f, 1e30f, 0.75f), 1.0f, Vec3(1.0f), Vec3(0, 0, 1), 1.0f, 0);
  EXPECT_DOUBLE_EQ(acc.contrast(0), (5.0 - -1.0) / (5.0 + -1.0));
  EXPECT_DOUBLE_EQ(acc.contrast(2), 0.5);
}

// A large film's pages are not resident until written or populated; populating a rectangle
// maps its rows' pages (and no others far from it) and leaves the values as they were.
TEST(Film, PagesAreMappedOnlyWherePopulatedOrWritten) {
  const long page = sysconf(_SC_PAGESIZE);
  Film film(512, 64);  // 512 * 224 bytes a row: 28 pages
  // Resident pages of the pages row y spans (28 or 29: rows need not start on a page).
  const auto resident = [&](int y) {
    const uintptr_t a = reinterpret_cast<uintptr_t>(&film.at(0, y)) & ~uintptr_t(page - 1);
    const uintptr_t b = reinterpret_cast<uintptr_t>(&film.at(511, y) + 1);
    std::vector<unsigned char> v((b - a + page - 1) / page);
    EXPECT_EQ(mincore(reinterpret_cast<void*>(a), b - a, v.data()), 0);
    int n = 0;
    for (unsigned char c : v) n += c & 1;
    return std::pair<int, int>(n, int(v.size()));
  };
  for (int y : {0, 20, 63}) EXPECT_EQ(resident(y).first, 0) << y;
  film.at(100, 10).add(Vec3(0.5f), 1.0f, Vec3(1.0f), Vec3(0, 0, 1), 1.0f, 0);
  EXPECT_GE(resident(10).first, 1);
  {
    void* probe = mmap(nullptr, std::size_t(page), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    ASSERT_NE(probe, MAP_FAILED);
    const bool can = madvise(probe, std::size_t(page), MADV_POPULATE_WRITE) == 0;
    munmap(probe, std::size_t(page));
    if (!can) GTEST_SKIP() << "this kernel has no MADV_POPULATE_WRITE (Linux < 5.14): populate does nothing";
  }
  film.populate(0, 512, 20, 24);
  for (int y = 20; y < 24; ++y) EXPECT_EQ(resident(y).first, resident(y).second) << y;
  film.populate(64, 128, 40, 42);
  EXPECT_GE(resident(40).first, 4);  // 64 pixels: 14,336 bytes over 4 or 5 pages, not the row's 28
  EXPECT_LE(resident(40).first, 5);
  EXPECT_EQ(resident(50).first, 0);
  film.populate(0, 512, 9, 12);
  EXPECT_EQ(film.at(100, 10).samples, 1);
  EXPECT_FLOAT_EQ(film.at(100, 10).value().x, 0.5f);
}
