// `zsobol` (Ahmed & Wonka 2020): per-pixel nets, nets over groups of neighbouring pixels,
// digit permutations that keep blocks aligned, unbiasedness over seeds, and refusals.
#include "sampling/samplers/zsobol_sampler.h"

#include "sampling/core/errors.h"
#include "sampling/measures/elementary_intervals.h"
#include "tests/support/sampler_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <thread>
#include <vector>

namespace pdrt {
namespace {

PointSet points_of(const Sampler& s, const std::vector<std::array<int, 2>>& pixels, int n, Family f, int bounce) {
  return test::stream_points(s, pixels, n, f, bounce);
}

TEST(ZSobolSampler, EveryPixelsBlockIsANet) {
  auto s = make_zsobol_sampler(3, {16, 64, 48});
  for (int y = 0; y < 48; y += 7)
    for (int x = 0; x < 64; x += 5)
      for (Family f : {Family::Pixel, Family::Lens, Family::Gloss})
        ASSERT_TRUE(is_02_net(points_of(*s, {{x, y}}, 16, f, 2), 0, 16)) << x << "," << y;
}

TEST(ZSobolSampler, AlignedTwoByTwoPixelGroupsTogetherFormANet) {
  // The screen-space property: the 4 pixels of an aligned 2x2 group take one aligned block
  // of 4 x 16 Sobol indices, so their 64 samples are a (0,6,2)-net; so are 4x4 groups (256).
  auto s = make_zsobol_sampler(11, {16, 32, 32});
  for (int y = 0; y < 32; y += 2)
    for (int x = 0; x < 32; x += 2)
      ASSERT_TRUE(
          is_02_net(points_of(*s, {{x, y}, {x + 1, y}, {x, y + 1}, {x + 1, y + 1}}, 16, Family::Light, 0), 0, 64));
  std::vector<std::array<int, 2>> group;
  for (int y = 4; y < 8; ++y)
    for (int x = 8; x < 12; ++x) group.push_back({x, y});
  EXPECT_TRUE(is_02_net(points_of(*s, group, 16, Family::Lens, 1), 0, 256));
}

TEST(ZSobolSampler, UnalignedPixelGroupsAreNotNetsSoTheTestCanFail) {
  // Pixels (1,0),(2,0),(1,1),(2,1) straddle two aligned groups: their samples are not one block.
  auto s = make_zsobol_sampler(11, {16, 32, 32});
  int nets = 0;
  for (int y = 0; y < 16; y += 2)
    nets += is_02_net(points_of(*s, {{1, y}, {2, y}, {1, y + 1}, {2, y + 1}}, 16, Family::Light, 0), 0, 64);
  EXPECT_LT(nets, 8);
}

TEST(ZSobolSampler, DigitPermutationIsABijectionKeepingAlignedBlocks) {
  for (int bits : {0, 1, 5, 6, 12}) {
    const uint32_t n = 1u << bits;
    std::set<uint32_t> seen;
    for (uint32_t z = 0; z < n; ++z) seen.insert(zsobol_sobol_index(z, bits, 0x1234 + bits));
    ASSERT_EQ(seen.size(), n);
    ASSERT_LT(*seen.rbegin(), n);
    // Digits are pairs of bits from the top (an odd count leaves the lowest bit alone), so
    // aligned blocks of 4 inputs (even counts) or of 2 and 8 (odd) land on aligned blocks.
    for (uint32_t size : bits % 2 ? std::vector<uint32_t>{2, 8} : std::vector<uint32_t>{4, 16})
      for (uint32_t z = 0; size <= n && z < n; z += size) {
        std::set<uint32_t> block;
        for (uint32_t d = 0; d < size; ++d) block.insert(zsobol_sobol_index(z + d, bits, 0x1234 + bits) / size);
        ASSERT_EQ(block.size(), 1u) << bits << " " << z;
      }
  }
}

TEST(ZSobolSampler, DimensionsAndSeedsTakeDifferentPixelOrders) {
  auto s = make_zsobol_sampler(5, {4, 16, 16}), t = make_zsobol_sampler(6, {4, 16, 16});
  int same_family = 0, same_seed = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      same_family += s->get_2d(x, y, 0, Family::Lens, 0) == s->get_2d(x, y, 0, Family::Light, 0);
      same_seed += s->get_2d(x, y, 0, Family::Lens, 0) == t->get_2d(x, y, 0, Family::Lens, 0);
    }
  EXPECT_EQ(same_family, 0);
  EXPECT_EQ(same_seed, 0);
}

TEST(ZSobolSampler, SamplesBeyondTheBlockAreANetPerBlock) {
  // Adaptive refinement past the block: samples [16, 32) are a fresh net, [0, 16) unchanged.
  auto s = make_zsobol_sampler(9, {16, 8, 8});
  PointSet p = points_of(*s, {{3, 4}}, 48, Family::Gloss, 4);
  EXPECT_TRUE(is_02_net(p, 0, 16));
  EXPECT_TRUE(is_02_net(p, 16, 16));
  EXPECT_TRUE(is_02_net(p, 32, 16));
}

TEST(ZSobolSampler, MeanOverSeedsIsUniform) {
  // Each value is uniform over seeds: the mean of x over 4096 seeds is 1/2 within 5 sigma
  // (sigma = sqrt(1/12 / 4096) = 0.0045), at a pixel away from the origin and far outside the image.
  for (auto [x, y] : std::vector<std::array<int, 2>>{{5, 9}, {-700, 100003}}) {
    double sx = 0, sy = 0, st = 0;
    const int n = 4096;
    for (int seed = 0; seed < n; ++seed) {
      auto s = make_zsobol_sampler(uint64_t(seed), {8, 16, 16});
      const Vec2 v = s->get_2d(x, y, 3, Family::Pixel, 0);
      sx += v[0], sy += v[1], st += s->get_1d(x, y, 5, Family::Time, 0);
    }
    EXPECT_NEAR(sx / n, 0.5, 0.0225);
    EXPECT_NEAR(sy / n, 0.5, 0.0225);
    EXPECT_NEAR(st / n, 0.5, 0.0225);
  }
}

// Over several blocks, with odd and even counts of index bits (3, 4, 5 and 6 + 10: one to
// three levels of sample digits, prepare keeping the upper ones per node) and a pixel outside
// the image (it wraps); and windows that start inside a block (a later pass).
TEST(ZSobolSampler, PreparedStreamMatchesValueByValue) {
  for (int spp : {8, 16, 32, 64}) {
    auto s = make_zsobol_sampler(21, {spp, 20, 12});
    for (Family f : {Family::Pixel, Family::Time})
      for (int px : {7, 45}) {
        EXPECT_EQ(test::prepared_mismatches(*s, px, 3, f, 1, 70), 0) << spp << " " << px;
        for (uint32_t first : {4u, 13u, 16u, 69u})
          EXPECT_EQ(test::prepared_mismatches(*s, px, 3, f, 1, 70, first), 0) << spp << " " << px << " " << first;
      }
  }
}

// A thread keeps each block key's Morton digits from pixel to pixel (rehashing only those
// below the highest changed bit): a value must not depend on which pixels came before it.
TEST(ZSobolSampler, ValuesDoNotDependOnThePixelsAskedBefore) {
  auto s = make_zsobol_sampler(5, {4, 64, 64});
  std::vector<std::array<int, 2>> raster, shuffled;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) raster.push_back({x, y});
  shuffled = raster;
  for (std::size_t i = shuffled.size() - 1; i > 0; --i) std::swap(shuffled[i], shuffled[(i * 7919 + 13) % (i + 1)]);
  // Values per pixel, each pixel asked in `order`, in a thread of its own (fresh caches).
  const auto values = [&](const std::vector<std::array<int, 2>>& order) {
    std::vector<double> v(raster.size() * 6 * 3);
    std::thread([&] {
      const int64_t indices[6] = {0, 1, 3, 5, 17, 64};  // blocks 0, 1, 4 and 16
      for (const auto& p : order)
        for (int k = 0; k < 6; ++k) {
          const int64_t i = indices[k];
          const std::size_t at = (std::size_t(p[1] * 16 + p[0]) * 6 + std::size_t(k)) * 3;
          const Vec2 u = s->get_2d(p[0], p[1], i, Family::Light, 1);
          v[at] = u[0], v[at + 1] = u[1], v[at + 2] = s->get_1d(p[0], p[1], i, Family::Time, 4);
        }
    }).join();
    return v;
  };
  EXPECT_EQ(values(raster), values(shuffled));
}

TEST(ZSobolSampler, RefusesImagesItCannotOrder) {
  // 4096 x 4096 needs 24 Morton bits; 1024 spp 10 more.
  try {
    make_zsobol_sampler(1, {1024, 4096, 4096});
    FAIL() << "accepted 34 index bits";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("4096 x 4096 pixels at 1024 samples per pixel need 34 bits"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(make_zsobol_sampler(1, {256, 4096, 4096}));
  EXPECT_THROW(make_zsobol_sampler(1, {0, 16, 16}), UsageError);
}

}  // namespace
}  // namespace pdrt
