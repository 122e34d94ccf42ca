#include "sampling/core/rng.h"
#include "sampling/generators/detail/two_disk_cover.h"

#include <gtest/gtest.h>

namespace pdrt {
namespace {

bool in_disk(double x, double y, const double* c, double r2) {
  return (x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) < r2;
}

// Dense probing of the square (boundary and interior): false when a probe is in neither disk.
bool probe_covered(const double* lo, double w, const double* a, const double* b, double r2, int m = 200) {
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= m; ++j) {
      const double x = lo[0] + w * i / m, y = lo[1] + w * j / m;
      if (!in_disk(x, y, a, r2) && !in_disk(x, y, b, r2)) return false;
    }
  return true;
}

TEST(TwoDiskCover, SquareCoveredOnlyByBothDisksTogether) {
  // Unit disks at (0, 0) and (1.6, 0); the square [0.6, 1.0] x [-0.2, 0.2] straddles the
  // lens between them. Neither disk holds its far corners, together they hold it all.
  const double a[2] = {0.0, 0.0}, b[2] = {1.6, 0.0}, lo[2] = {0.6, -0.2};
  EXPECT_FALSE(probe_covered(lo, 0.4, a, a, 1.0));
  EXPECT_FALSE(probe_covered(lo, 0.4, b, b, 1.0));
  EXPECT_TRUE(probe_covered(lo, 0.4, a, b, 1.0));
  EXPECT_TRUE(square_in_two_disks(lo, 0.4, a, b, 1.0));
}

TEST(TwoDiskCover, GapBetweenDisksIsNotCovered) {
  // Disks at (0, 0) and (2.1, 0): a 0.1-wide gap on the x axis crosses the square.
  const double a[2] = {0.0, 0.0}, b[2] = {2.1, 0.0}, lo[2] = {0.9, -0.1};
  EXPECT_FALSE(square_in_two_disks(lo, 0.3, a, b, 1.0));
}

TEST(TwoDiskCover, NeverCoveredWhereProbingFindsAHole) {
  // Random squares near two random unit disks: the test may say "not covered" for a covered
  // square (it is only used to prune), but never "covered" when a probe is uncovered; and it
  // must find most covered squares (a test that never prunes would be useless).
  Rng rng(7, 1);
  int covered = 0, found = 0;
  for (int t = 0; t < 3000; ++t) {
    const double a[2] = {rng.uniform(-1, 1), rng.uniform(-1, 1)}, b[2] = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double w = rng.uniform(0.05, 0.8), lo[2] = {rng.uniform(-1, 1) - w / 2, rng.uniform(-1, 1) - w / 2};
    const bool says = square_in_two_disks(lo, w, a, b, 1.0);
    const bool truth = probe_covered(lo, w, a, b, 1.0, 60);
    if (says) {
      EXPECT_TRUE(truth) << t;
    }
    covered += truth;
    found += says && truth;
  }
  ASSERT_GT(covered, 300);
  EXPECT_GT(found, covered * 0.95);  // misses only squares whose probes graze the disks' edges
}

TEST(TwoDiskCover, EdgeTouchingACircleFromOutsideIsNotCovered) {
  // The square's corner lies exactly on disk a's circle and outside b: open disks miss it.
  const double a[2] = {0.0, 0.0}, b[2] = {5.0, 5.0}, lo[2] = {1.0, 0.0};
  EXPECT_FALSE(square_in_two_disks(lo, 0.1, a, b, 1.0));
}

}  // namespace
}  // namespace pdrt
