// FNV-1a: the published 64-bit test vectors, so table checksums and cache keys never drift.
#include "sampling/core/hash.h"

#include <gtest/gtest.h>

namespace pdrt {
namespace {

TEST(Fnv1a, MatchesThePublishedTestVectors) {
  EXPECT_EQ(fnv1a(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a("foobar"), 0x85944171f73967e8ull);
}

}  // namespace
}  // namespace pdrt
