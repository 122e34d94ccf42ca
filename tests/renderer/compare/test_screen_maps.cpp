// The pictures of the screen-space measures (renderer/compare/screen_maps.h).
#include "renderer/compare/screen_maps.h"

#include <gtest/gtest.h>

using namespace pdrt;

// The spectrum images put DC at the centre, (W / 2, H / 2), and the highest frequency
// (-0.5, -0.5) in the first row and column.
TEST(ScreenMaps, CentredSpectrumPutsDcInTheMiddle) {
  std::vector<double> p(6 * 4, 0.0);
  p[0] = 1, p[2 * 6 + 3] = 2;
  const std::vector<double> c = centred_spectrum(p, 6, 4);
  EXPECT_EQ(c[2 * 6 + 3], 1.0);
  EXPECT_EQ(c[0], 2.0);
}
