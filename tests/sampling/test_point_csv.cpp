// The point CSV: what write_point_csv writes, read_point_csv reads back exactly.
#include "sampling/core/point_csv.h"
#include "sampling/core/rng.h"
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace pdrt {
namespace {

TEST(PointCsv, WriteThenReadGivesIdenticalDoubles) {
  PointSet ps;
  ps.dim = 3;
  // Values that need all 17 significant digits, the extremes of [0,1), and tiny radii.
  const double edge[] = {0.0, std::nextafter(1.0, 0.0), 0.1, 1.0 / 3.0, 5e-324, 2.2250738585072014e-308, 1e-5};
  for (double v : edge)
    ps.coords.insert(ps.coords.end(), {v, 1.0 - std::nextafter(1.0, 0.0), 0.5}), ps.radius.push_back(v);
  Rng rng(7);
  for (int i = 0; i < 5000; ++i) {
    for (int k = 0; k < 3; ++k) ps.coords.push_back(rng.uniform());
    ps.radius.push_back(rng.uniform() * 1e-3);
  }
  const auto path = test::scratch_dir("point_csv") / "p.csv";
  write_point_csv(path, ps);
  PointSet back = read_point_csv(path);
  ASSERT_EQ(back.dim, 3);
  ASSERT_EQ(back.coords.size(), ps.coords.size());
  ASSERT_EQ(back.radius.size(), ps.radius.size());
  for (std::size_t i = 0; i < ps.coords.size(); ++i) ASSERT_EQ(back.coords[i], ps.coords[i]) << "value " << i;
  for (std::size_t i = 0; i < ps.radius.size(); ++i) ASSERT_EQ(back.radius[i], ps.radius[i]) << "radius " << i;
}

TEST(PointCsv, WritesShortestFormOfEachValue) {
  PointSet ps;
  ps.dim = 2;
  ps.coords = {0.5, 0.1, 0.0, 0.25};
  const auto path = test::scratch_dir("point_csv_short") / "p.csv";
  write_point_csv(path, ps);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "x0,x1\n0.5,0.1\n0,0.25\n");
}

}  // namespace
}  // namespace pdrt
