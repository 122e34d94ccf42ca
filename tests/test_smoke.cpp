#include <gtest/gtest.h>
#include "generator.h"
TEST(Smoke, Builds) { EXPECT_NEAR(pdrt::max_packing_distance(1, 1), 1.0, 1e-12); }
