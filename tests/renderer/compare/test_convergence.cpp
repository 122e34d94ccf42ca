// Error-versus-cost curves (renderer/convergence.h): slopes and the cost to reach an error.
#include "renderer/compare/convergence.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;

TEST(Convergence, SlopeOfAPowerLaw) {
  std::vector<double> x{1, 4, 16, 64}, y;
  for (double v : x) y.push_back(3 * std::pow(v, -0.5));
  EXPECT_NEAR(loglog_slope(x, y), -0.5, 1e-12);
}

TEST(Convergence, InterpolationIsLinearInLogLogAndNaNOutside) {
  std::vector<double> x{1, 100}, y{1, 0.01};  // y = 1/x
  EXPECT_NEAR(loglog_interp(x, y, 10), 0.1, 1e-12);
  EXPECT_TRUE(std::isnan(loglog_interp(x, y, 0.5)));
  EXPECT_TRUE(std::isnan(loglog_interp(x, y, 200)));
}

TEST(Convergence, CostToReachInterpolatesTheCrossingSegment) {
  // error = 1/sqrt(cost); error 0.25 is reached at cost 16, between the points 4 and 64.
  std::vector<double> cost{64, 4, 1}, err{0.125, 0.5, 1};  // unsorted on purpose
  CostToReach c = cost_to_reach(cost, err, 0.25);
  EXPECT_NEAR(c.cost, 16, 1e-9);
  EXPECT_FALSE(c.upper_bound);
}

TEST(Convergence, CostToReachTakesTheFirstCrossing) {
  // Not monotone: the curve dips below 0.3 between 2 and 4, rises, and falls again.
  std::vector<double> cost{1, 2, 4, 8, 16}, err{1, 0.4, 0.2, 0.5, 0.1};
  CostToReach c = cost_to_reach(cost, err, 0.3);
  EXPECT_GT(c.cost, 2);
  EXPECT_LT(c.cost, 4);
}

TEST(Convergence, CostToReachBoundsAndMisses) {
  std::vector<double> cost{10, 20}, err{0.1, 0.05};
  CostToReach already = cost_to_reach(cost, err, 0.2);
  EXPECT_EQ(already.cost, 10);
  EXPECT_TRUE(already.upper_bound) << "the cheapest run already reaches the target";
  EXPECT_TRUE(std::isnan(cost_to_reach(cost, err, 0.01).cost)) << "no run reaches it";
  EXPECT_TRUE(std::isnan(cost_to_reach({}, {}, 0.1).cost));
}
