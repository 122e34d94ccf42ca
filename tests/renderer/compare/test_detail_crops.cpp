// The detail window of `pdrt compare`'s crops and demonstration sheet (renderer/compare/detail_crops.h).
#include "renderer/compare/detail_crops.h"
#include "tests/support/image_fixtures.h"

#include <gtest/gtest.h>

using namespace pdrt;

TEST(DetailWindow, SideIsAQuarterOfTheShorterSideAndAtLeastEight) {
  EXPECT_EQ(detail_window(test::random_image(128, 64, 1, 0, 1))[2], 16);
  EXPECT_EQ(detail_window(test::random_image(40, 20, 1, 0, 1))[2], 8);
}

// A film under 8 pixels on a side (a test scene of 8 x 6): the window is the shorter side and
// lies inside the image.
TEST(DetailWindow, TinyImageGetsAWindowInsideIt) {
  for (auto [w, h] : {std::array<int, 2>{8, 6}, {6, 8}, {3, 3}, {1, 5}}) {
    const auto [x, y, c] = detail_window(test::random_image(w, h, 2, 0, 1));
    EXPECT_EQ(c, std::min(w, h)) << w << "x" << h;
    EXPECT_GE(x, 0);
    EXPECT_GE(y, 0);
    EXPECT_LE(x + c, w) << w << "x" << h;
    EXPECT_LE(y + c, h) << w << "x" << h;
  }
}
