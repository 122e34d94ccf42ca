// `poisson-ss` (issue 31 item 1): the tables in progressive order, nets over aligned groups of
// neighbouring pixels in every family, the digit scramble's split form, the nested order of a pixel's samples, values
// independent of the thread's caches, replay, unbiasedness over seeds, refinement blocks, and refusals.
#include "sampling/samplers/screen_poisson_sampler.h"

#include "sampling/core/errors.h"
#include "sampling/core/rng.h"
#include "sampling/measures/elementary_intervals.h"
#include "sampling/samplers/progressive_order.h"
#include "tests/support/sampler_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace pdrt {
namespace {

PointSet table_points(const std::vector<uint32_t>& c, const std::vector<uint32_t>* order) {
  PointSet ps;
  ps.dim = 2;
  ps.periodic = true;
  for (std::size_t j = 0; j < c.size() / 2; ++j) {
    const std::size_t i = order ? (*order)[j] : j;
    ps.coords.push_back(unit_from_u32(c[2 * i]));
    ps.coords.push_back(unit_from_u32(c[2 * i + 1]));
  }
  return ps;
}

// Aligned blocks of 2^s points, s = 1..10, that are not (0,s,2)-nets.
int broken_blocks(const PointSet& ps) {
  int broken = 0;
  const std::size_t n = ps.coords.size() / 2;
  for (std::size_t size = 2; size <= n; size *= 2)
    for (std::size_t a = 0; a < n; a += size) broken += !is_02_net(ps, a, size);
  return broken;
}

std::unique_ptr<Sampler> screen(uint64_t seed, SamplerShape shape) {
  return make_screen_poisson_sampler(seed, default_tables(), shape);
}

std::vector<std::array<int, 2>> square(int x0, int y0, int side) {
  std::vector<std::array<int, 2>> p;
  for (int y = y0; y < y0 + side; ++y)
    for (int x = x0; x < x0 + side; ++x) p.push_back({x, y});
  return p;
}

// Table t of a default family's in progressive order (empty when it has none).
std::vector<uint32_t> order_of(Family f, uint32_t t) {
  const SampleTable& s = *default_tables().family[int(f)];
  std::string why;
  const auto order = progressive_order(s.coords[t].data(), s.params.points, s.dim, &why);
  EXPECT_TRUE(order) << why;
  return order ? *order : std::vector<uint32_t>{};
}

TEST(ProgressiveOrder, EveryAlignedBlockOfTheOwenPdTablesIsANet) {
  const SampleTable& t = *default_tables().family[int(Family::Lens)];
  for (uint32_t k = 0; k < t.table_count(); ++k) {
    const std::vector<uint32_t> order = order_of(Family::Lens, k);
    ASSERT_EQ(order.size(), t.params.points);
    EXPECT_EQ(broken_blocks(table_points(t.coords[k], &order)), 0);
  }
}

TEST(ProgressiveOrder, StoredFarthestFirstOrderBreaksAlignedBlocksSoTheTestCanFail) {
  const SampleTable& t = *default_tables().family[int(Family::Lens)];
  EXPECT_GT(broken_blocks(table_points(t.coords[0], nullptr)), 100);
}

TEST(ProgressiveOrder, KeepsThePowerOfTwoPrefixesAsSets) {
  const SampleTable& t = *default_tables().family[int(Family::Gloss)];
  const std::vector<uint32_t> order = order_of(Family::Gloss, 3);
  ASSERT_EQ(order.size(), t.params.points);
  for (uint32_t n = 1; n <= t.params.points; n *= 2) {
    std::set<uint32_t> a(order.begin(), order.begin() + n);
    EXPECT_EQ(a.size(), n);
    EXPECT_LT(*a.rbegin(), n);
  }
}

TEST(ProgressiveOrder, TimeTablesAlignedBlocksAreStratified) {
  const SampleTable& t = *default_tables().family[int(Family::Time)];
  for (uint32_t k = 0; k < t.table_count(); ++k) {
    const std::vector<uint32_t> order = order_of(Family::Time, k);
    ASSERT_EQ(order.size(), t.params.points);
    for (uint32_t size = 2; size <= t.params.points; size *= 2)
      for (uint32_t a = 0; a < t.params.points; a += size) {
        std::set<uint32_t> strata;
        for (uint32_t j = a; j < a + size; ++j) strata.insert(t.coords[k][order[j]] >> (32 - std::countr_zero(size)));
        ASSERT_EQ(strata.size(), size);
      }
  }
}

TEST(ProgressiveOrder, RefusesTablesWithoutStratifiedPrefixes) {
  std::vector<uint32_t> c(2 * 64);
  Rng rng(7, 1);
  for (auto& v : c) v = uint32_t(rng.next_u64());
  std::string why;
  EXPECT_FALSE(progressive_order(c.data(), 64, 2, &why));
  EXPECT_NE(why.find("not stratified"), std::string::npos) << why;
  EXPECT_FALSE(progressive_order(c.data(), 48, 2, &why));
  EXPECT_NE(why.find("not a power of two"), std::string::npos) << why;
}

TEST(ScrambleDigits, SplitAtThePixelBitsEqualsTheWholeAndIsABijectionKeepingAlignedBlocks) {
  for (int bits : {0, 1, 6, 9, 12}) {
    const uint32_t n = 1u << bits;
    std::set<uint32_t> seen;
    for (int m = bits % 2; m <= bits; m += 2)
      for (uint32_t z = 0; z < n; ++z)
        ASSERT_EQ(scramble_digits(z, bits, 0, 99), scramble_digits(z, bits, m, 99) | scramble_digits(z, m, 0, 99));
    for (uint32_t z = 0; z < n; ++z) seen.insert(scramble_digits(z, bits, 0, 5));
    ASSERT_EQ(seen.size(), n);
    for (uint32_t size = 4; size < n; size *= 4) {  // blocks of 4^j from the low end stay aligned
      const uint32_t s = bits % 2 ? size * 2 : size;
      if (s > n) break;
      for (uint32_t a = 0; a < n; a += s) {
        std::set<uint32_t> block;
        for (uint32_t d = 0; d < s; ++d) block.insert(scramble_digits(a + d, bits, 0, 5) / s);
        ASSERT_EQ(block.size(), 1u);
      }
    }
  }
}

TEST(ScreenPoissonSampler, EveryPixelAndEveryAlignedPixelGroupIsANetInEveryPlaneFamily) {
  // 4 spp: a pixel's 4 samples are a (0,2,2)-net, an aligned 2x2 group's 16 a (0,4,2)-net, and
  // so on up to the 16 x 16 pixels of one table run (1024 samples).
  auto s = screen(3, {4, 40, 24});
  for (Family f : {Family::Pixel, Family::Lens, Family::Light, Family::Gloss})
    for (int bounce : {0, 3})
      for (int side = 1; side <= 16; side *= 2)
        for (int y = 0; y + side <= 32; y += side * 3)
          for (int x = 0; x + side <= 48; x += side * 5)
            ASSERT_TRUE(is_02_net(test::stream_points(*s, square(x, y, side), 4, f, bounce), 0, 4 * side * side))
                << family_name(f) << " bounce " << bounce << " side " << side << " at " << x << "," << y;
}

TEST(ScreenPoissonSampler, UnalignedPixelGroupsAreNotNetsSoTheTestCanFail) {
  auto s = screen(3, {4, 32, 32});
  int nets = 0;
  for (int y = 0; y < 16; y += 2)
    nets += is_02_net(test::stream_points(*s, square(1, y, 2), 4, Family::Lens, 0), 0, 16);
  EXPECT_LT(nets, 8);
}

TEST(ScreenPoissonSampler, TimeSamplesOfAlignedPixelGroupsAreStratified) {
  auto s = screen(8, {2, 32, 32});
  for (int side = 1; side <= 16; side *= 2)
    for (int y = 0; y + side <= 32; y += side) {
      std::set<uint32_t> strata;
      for (auto [x, yy] : square(side, y, side))
        for (int i = 0; i < 2; ++i) strata.insert(uint32_t(s->get_1d(x, yy, i, Family::Time, 1) * 2.0 * side * side));
      ASSERT_EQ(strata.size(), std::size_t(2 * side * side)) << side;
    }
}

// prepare() fills a window block by block; every value equals the one asked alone: windows
// that start inside a block, a bounce past the threads' stream caches, blocks of an even and
// an odd count of sample bits (4 and 8 spp: an odd count ends in a single flipped bit), and
// (4096 spp) a pixel's block that spans four runs of the 2-D tables and two of the time tables.
TEST(ScreenPoissonSampler, PreparedStreamsMatchValueByValueAcrossBlocks) {
  for (int64_t spp : {4, 8}) {
    auto s = screen(21, {spp, 20, 12});
    for (Family f : {Family::Pixel, Family::Time, Family::Gloss})
      for (int bounce : {2, PixelSampleState::kCachedSalts + 3}) {
        EXPECT_EQ(test::prepared_mismatches(*s, 7, 3, f, bounce, 10 * spp), 0) << family_name(f) << spp;  // ten blocks
        EXPECT_EQ(test::prepared_mismatches(*s, 7, 3, f, bounce, 10 * spp + 3, 6), 0) << family_name(f) << spp;
      }
  }
  auto big = screen(22, {4096, 4, 4});
  for (Family f : {Family::Lens, Family::Time})
    EXPECT_EQ(test::prepared_mismatches(*big, 1, 2, f, 0, 4096 + 100, 1000), 0) << family_name(f);
}

// The values do not depend on what a thread's caches hold: the streams of a 20 x 12 image
// prepared pixel by pixel in rows (each pixel reuses the digits its neighbour left) equal the
// values another sampler of the same seed gives asked in the reverse order, at a cached bounce.
TEST(ScreenPoissonSampler, ValuesDoNotDependOnTheOrderPixelsAreVisited) {
  const SamplerShape shape{16, 20, 12};
  auto a = screen(31, shape), b = screen(31, shape);
  for (Family f : {Family::Lens, Family::Time}) {
    std::vector<double> prepared;
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 20; ++x) {
        PreparedStream p;
        p.first = 0, p.want = 16;
        a->prepare(x, y, f, 1, &p);
        ASSERT_TRUE(p.coords);
        for (int i = 0; i < 16; ++i) prepared.push_back(p.value(i, 0));
      }
    for (int y = 11; y >= 0; --y)
      for (int x = 19; x >= 0; --x)
        for (int i = 15; i >= 0; --i)
          ASSERT_EQ(prepared[std::size_t((y * 20 + x) * 16 + i)], b->get_1d(x, y, i, f, 1))
              << family_name(f) << " " << x << " " << y << " " << i;
  }
}

// A pixel's samples visit its block in nested order (base-4 digits permuted per node, an odd
// count of bits ending in a flipped pair): its first 4^j samples, and with an odd count of
// sample bits its first 2 * 4^j, are an aligned sub-block of the table's, so a (0, m, 2)-net
// (what a progressive render's passes and adaptive refinement see before the pixel's last
// pass).
TEST(ScreenPoissonSampler, PowerOfFourPrefixesOfAPixelAreNets) {
  for (int64_t spp : {64, 32})
    for (Family f : {Family::Pixel, Family::Lens, Family::Gloss}) {
      auto s = screen(17, {spp, 16, 16});
      for (auto [x, y] : square(3, 5, 3)) {
        PointSet ps;
        ps.dim = 2;
        for (int i = 0; i < spp; ++i) {
          const Vec2 v = s->get_2d(x, y, i, f, 0);
          ps.coords.push_back(v[0]), ps.coords.push_back(v[1]);
        }
        for (std::size_t n = spp == 64 ? 4 : 2; n <= std::size_t(spp); n *= 4)
          ASSERT_TRUE(is_02_net(ps, 0, n)) << family_name(f) << " " << spp << " " << n;
      }
    }
}

TEST(ScreenPoissonSampler, RefinementBlocksAreScreenSpacePatternsOfTheirOwn) {
  // A pixel past its 4 samples takes block b = index / 4 of a fresh arrangement: samples 4..7
  // of each pixel are a net, and so are those of an aligned 2 x 2 group; pixels refined together
  // stay complementary, and a neighbour's first block is untouched (values are pure functions).
  auto s = screen(13, {4, 16, 16});
  for (int y = 0; y < 16; y += 2)
    for (int x = 0; x < 16; x += 2) {
      PointSet ps;
      ps.dim = 2;
      for (auto [px, py] : square(x, y, 2))
        for (int i = 4; i < 8; ++i) {
          const Vec2 v = s->get_2d(px, py, i, Family::Lens, 0);
          ps.coords.push_back(v[0]), ps.coords.push_back(v[1]);
        }
      ASSERT_TRUE(is_02_net(ps, 0, 16));
      ASSERT_TRUE(is_02_net(ps, 0, 4));
    }
  // Block 1 differs from block 0 (a fresh arrangement, not a repeat).
  EXPECT_NE(s->get_2d(3, 3, 0, Family::Lens, 0), s->get_2d(3, 3, 4, Family::Lens, 0));
}

TEST(ScreenPoissonSampler, EstimateOfAnAnalyticIntegralIsUnbiasedOverSeeds) {
  // f(pixel, lens, time) = x y + u^2 + sin(pi t) with integral 1/4 + 1/3 + 2/pi, estimated from
  // a pixel's 4 samples; the mean over 2048 seeds is within 4 standard errors of the integral,
  // at a pixel inside and one outside the image, at samples of the first and a later block.
  for (auto [px, py, first] : std::vector<std::array<int, 3>>{{5, 9, 0}, {-70, 1003, 8}}) {
    const auto [mean, se] = test::analytic_estimate(
        [](uint64_t seed) {
          return screen(seed, {4, 16, 16});
        },
        px, py, first);
    EXPECT_NEAR(mean, test::analytic_estimate_integral, 4 * se) << px << "," << py;
    EXPECT_GT(se, 0.0);
  }
}

TEST(ScreenPoissonSampler, RefusesImagesItCannotOrder) {
  try {
    screen(1, {1024, 4096, 4096});
    FAIL() << "no refusal";
  } catch (const UsageError& e) {
    EXPECT_NE(
        std::string(e.what()).find("sampler poisson-ss: 4096 x 4096 pixels at 1024 samples per pixel need 34 bits"),
        std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(screen(1, {256, 4096, 4096}));
  EXPECT_THROW(screen(1, {0, 16, 16}), UsageError);
}

TEST(ScreenPoissonSampler, RefusesTiledPixelTables) {
  TableSet set = default_tables();
  SampleTable tiled = *set.family[int(Family::Pixel)];
  tiled.params.tile = 2;
  set.family[int(Family::Pixel)] = std::make_shared<const SampleTable>(tiled);
  try {
    make_screen_poisson_sampler(1, set, {4, 16, 16});
    FAIL() << "no refusal";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("tiled"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pdrt
