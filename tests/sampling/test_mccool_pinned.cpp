// `mccool` output pinned bit for bit: the default tables are made by this generator, so a
// speed-up must not move a single point (hash of every coordinate and radius bit).
#include "sampling/generators/generator.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

namespace pdrt {
namespace {

// FNV-1a over the IEEE bits of the coordinates, then of the radii.
uint64_t bits_hash(const PointSet& ps) {
  uint64_t h = 0xcbf29ce484222325ull;
  auto eat = [&](double v) {
    uint64_t b = std::bit_cast<uint64_t>(v);
    for (int i = 0; i < 8; ++i) h = (h ^ ((b >> (8 * i)) & 0xff)) * 0x100000001b3ull;
  };
  for (double v : ps.coords) eat(v);
  for (double v : ps.radius) eat(v);
  return h;
}

uint64_t mccool_hash(int dim, int64_t count, bool periodic, uint64_t seed) {
  GeneratorParams p;
  p.method = "mccool";
  p.dim = dim;
  p.count = count;
  p.periodic = periodic;
  p.seed = seed;
  PointSet ps = generate(p);
  EXPECT_EQ(ps.size(), std::size_t(count));
  return bits_hash(ps);
}

// Values recorded from the generator before the 2-D grid rewrite (commit 102ee03).
TEST(McCoolPinned, TwoDimensionalBounded) {
  EXPECT_EQ(mccool_hash(2, 300, false, 7), 0x71a2a28a40e1b81eull);
  EXPECT_EQ(mccool_hash(2, 4096, false, 5), 0x1259ee4304859883ull);
}

TEST(McCoolPinned, TwoDimensionalPeriodic) {
  EXPECT_EQ(mccool_hash(2, 300, true, 7), 0xe0ab5d4d71a1b1e5ull);
  EXPECT_EQ(mccool_hash(2, 4096, true, 5), 0x1c941da98c7b21ffull);
}

TEST(McCoolPinned, OtherDimensions) {
  EXPECT_EQ(mccool_hash(1, 1024, true, 3), 0x791172f47366d5f5ull);
  EXPECT_EQ(mccool_hash(3, 500, false, 3), 0xbb6c28256b182457ull);
}

}  // namespace
}  // namespace pdrt
