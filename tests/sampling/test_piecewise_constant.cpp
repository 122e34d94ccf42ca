// Tabulated distributions: samples follow the tabulated function (chi-square), the pdf is the
// normalised function, zero cells are never drawn, and the inversion is monotone.
#include "sampling/core/piecewise_constant.h"

#include "sampling/analysis/incomplete_gamma.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pdrt {
namespace {

TEST(PiecewiseConstant, OneDimensionalSamplesFollowTheFunction) {
  // f = 0, 1, 3, 0, 2, -4 (negative read as 4) on [-2, 4): chi-square p > 0.001 over the 4
  // cells with mass, no sample in a zero cell, pdf = |f| / integral.
  const std::vector<double> f = {0, 1, 3, 0, 2, -4};
  PiecewiseConstant1D d(f, -2, 4);
  EXPECT_DOUBLE_EQ(d.integral(), 10.0);
  Rng rng(3);
  const int n = 100000;
  std::vector<int> count(f.size());
  for (int i = 0; i < n; ++i) {
    double pdf = 0;
    std::size_t cell = 0;
    double x = d.sample(rng.uniform(), &pdf, &cell);
    ASSERT_GE(x, -2.0);
    ASSERT_LT(x, 4.0);
    ASSERT_EQ(cell, std::size_t(std::floor(x + 2)));
    ASSERT_DOUBLE_EQ(pdf, std::abs(f[cell]) / 10.0);
    ASSERT_DOUBLE_EQ(d.pdf(x), pdf);
    ++count[cell];
  }
  EXPECT_EQ(count[0], 0);
  EXPECT_EQ(count[3], 0);
  double chi = 0;
  int dof = -1;
  for (std::size_t k = 0; k < f.size(); ++k) {
    double e = n * std::abs(f[k]) / 10.0;
    if (e == 0) continue;
    chi += (count[k] - e) * (count[k] - e) / e, ++dof;
  }
  EXPECT_GT(chi_square_p_value(chi, dof), 1e-3) << chi;
}

TEST(PiecewiseConstant, InversionIsMonotoneAndContinuous) {
  // Increasing u gives non-decreasing x, and nearby u give nearby x (no jumps across the
  // zero cell): what keeps a stratified input pattern stratified.
  PiecewiseConstant1D d({2, 0, 1, 5}, 0, 1);
  double prev = -1;
  for (int i = 0; i < 10000; ++i) {
    double x = d.sample((i + 0.5) / 10000, nullptr);
    ASSERT_GE(x, prev);
    if (prev >= 0) {
      ASSERT_LT(x - prev, 0.25 + 1e-3) << "only the zero cell may be skipped";
    }
    prev = x;
  }
}

TEST(PiecewiseConstant, AllZeroSamplesUniformly) {
  PiecewiseConstant1D d({0, 0, 0, 0}, 1, 3);
  EXPECT_EQ(d.integral(), 0.0);
  double pdf = 0;
  EXPECT_NEAR(d.sample(0.625, &pdf), 2.25, 1e-12);
  EXPECT_DOUBLE_EQ(pdf, 0.5);
}

TEST(PiecewiseConstant, TwoDimensionalPdfIsTheNormalisedFunction) {
  // 3 x 2 cells on [10, 13) x [-1, 1): every sample's pdf equals f / integral of f, the cell
  // frequencies follow f (chi-square), and the empty cell gets nothing.
  const std::vector<double> f = {1, 2, 0, 4, 0.5, 3};
  PiecewiseConstant2D d(f, 3, 2, 10, 13, -1, 1);
  const double total = (1 + 2 + 0 + 4 + 0.5 + 3) * 1.0;  // cell area 1 x 1
  EXPECT_DOUBLE_EQ(d.integral(), total);
  Rng rng(5);
  const int n = 100000;
  std::vector<int> count(6);
  for (int i = 0; i < n; ++i) {
    double pdf = 0;
    auto p = d.sample({rng.uniform(), rng.uniform()}, &pdf);
    int cx = int(std::floor(p[0] - 10)), cy = int(std::floor(p[1] + 1));
    ASSERT_TRUE(cx >= 0 && cx < 3 && cy >= 0 && cy < 2);
    ASSERT_NEAR(pdf, f[cy * 3 + cx] / total, 1e-12);
    ASSERT_NEAR(d.pdf(p[0], p[1]), pdf, 1e-12);
    ++count[cy * 3 + cx];
  }
  EXPECT_EQ(count[2], 0);
  double chi = 0;
  int dof = -1;
  for (int k = 0; k < 6; ++k) {
    double e = n * f[k] / total;
    if (e == 0) continue;
    chi += (count[k] - e) * (count[k] - e) / e, ++dof;
  }
  EXPECT_GT(chi_square_p_value(chi, dof), 1e-3) << chi;
  EXPECT_EQ(d.pdf(9.99, 0), 0.0);
}

}  // namespace
}  // namespace pdrt
