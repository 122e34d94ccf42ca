// McCool–Fiume §5.2 importance by rank threshold, on the default lens tables.
#include "sampling/analysis/incomplete_gamma.h"
#include "sampling/samplers/poisson_sampler.h"
#include "sampling/samplers/rank_threshold.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pdrt {
namespace {

std::vector<Vec2> table_points(uint32_t table, std::size_t n) {
  const SampleTable& t = *default_tables().family[int(Family::Lens)];
  std::vector<Vec2> v(n);
  for (std::size_t i = 0; i < n; ++i)
    v[i] = {t.coords[table][2 * i] * 0x1.0p-32, t.coords[table][2 * i + 1] * 0x1.0p-32};
  return v;
}

double estimate(const std::vector<Vec2>& c, const std::function<double(Vec2)>& f, double fmin, double fmax,
                const std::function<double(Vec2)>& g, std::optional<double> xint = std::nullopt) {
  RankSelection s = rank_threshold(c, f, fmin, fmax, xint);
  double sum = 0.0;
  for (std::size_t j = 0; j < s.kept.size(); ++j) sum += s.weight[j] * g(c[s.kept[j]]);
  return sum;
}

TEST(RankThreshold, KeptDensityFollowsTheImportance) {
  // f(x, y) = x: kept points must have density 2x. Chi-square over 10 columns, pooling the 16
  // lens tables (1024 candidates each); expected counts from ∫ 2x over each column.
  std::vector<double> hits(10, 0.0);
  double kept = 0.0;
  for (uint32_t t = 0; t < 16; ++t) {
    auto c = table_points(t, 1024);
    RankSelection s = rank_threshold(c, [](Vec2 p) { return p[0]; }, 0.0, 1.0);
    for (uint32_t i : s.kept) hits[std::min(9, int(c[i][0] * 10))] += 1, kept += 1;
  }
  double chi2 = 0.0;
  for (int b = 0; b < 10; ++b) {
    double expected = kept * ((b + 1) * (b + 1) - b * b) / 100.0;
    chi2 += (hits[b] - expected) * (hits[b] - expected) / expected;
  }
  EXPECT_GT(chi_square_p_value(chi2, 9), 1e-3) << "chi2 " << chi2;
  EXPECT_NEAR(kept / (16 * 1024), 0.5, 0.02);  // ∫x = 1/2
}

TEST(RankThreshold, GaussianIntegralConverges) {
  const double s = 0.15;
  auto g = [s](Vec2 p) { return std::exp(-((p[0] - .5) * (p[0] - .5) + (p[1] - .5) * (p[1] - .5)) / (2 * s * s)); };
  const double side = s * std::sqrt(2 * std::numbers::pi) * std::erf(0.5 / (s * std::sqrt(2.0)));
  const double exact = side * side, fmin = g({0.0, 0.0});
  // With independent uniform candidates and ranks, each candidate adds g/x with probability
  // x, so the relative RMS error is sqrt((∫g²/x - (∫g)²) / n) / ∫g (midpoint rule below).
  double g2_over_x = 0.0;
  const int m = 400;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      Vec2 p{(i + 0.5) / m, (j + 0.5) / m};
      double x = (g(p) - fmin) / (1.0 - fmin);
      if (x > 0) g2_over_x += g(p) * g(p) / x / (double(m) * m);
    }
  double previous = 1e9;
  for (std::size_t n : {256, 1024}) {
    double err2 = 0.0;
    for (uint32_t t = 0; t < 16; ++t) {
      double e = estimate(table_points(t, n), g, fmin, 1.0, g) - exact;
      err2 += e * e / 16;
    }
    double rms = std::sqrt(err2) / exact, random_bound = std::sqrt((g2_over_x - exact * exact) / double(n)) / exact;
    // Converges: no worse than independent random candidates would be (x1.5 for the 16-table
    // estimate of the RMS), and shrinking with n.
    EXPECT_LT(rms, 1.5 * random_bound) << n;
    EXPECT_LT(rms, previous) << n;
    previous = rms;
  }
}

TEST(RankThreshold, NormalisedPhongLobeIntegratesToOne) {
  // Uniform hemisphere map z = u, phi = 2 pi v (d omega = 2 pi du dv): the normalised lobe
  // (e+1)/(2 pi) z^e integrates to 1. Importance f = z^e, closed-form ∫x = 1/(e+1).
  const double e = 20.0;
  auto f = [e](Vec2 p) { return std::pow(p[0], e); };
  auto g = [e, f](Vec2 p) { return (e + 1) / (2 * std::numbers::pi) * f(p) * 2 * std::numbers::pi; };
  double mean = 0.0;
  for (uint32_t t = 0; t < 16; ++t) mean += estimate(table_points(t, 1024), f, 0.0, 1.0, g, 1.0 / (e + 1)) / 16;
  EXPECT_NEAR(mean, 1.0, 1e-9);  // self-normalised: g/x is constant, so exact
  double plain = 0.0;
  for (uint32_t t = 0; t < 16; ++t) plain += estimate(table_points(t, 1024), f, 0.0, 1.0, g) / 16;
  EXPECT_NEAR(plain, 1.0, 0.05);  // k/n estimates ∫x = 1/21 from the table itself
}

TEST(RankThreshold, DiskAreaConverges) {
  auto g = [](Vec2 p) { return (p[0] - .5) * (p[0] - .5) + (p[1] - .5) * (p[1] - .5) < 0.09 ? 1.0 : 0.0; };
  auto f = [](Vec2 p) { return std::max(0.0, 1.0 - ((p[0] - .5) * (p[0] - .5) + (p[1] - .5) * (p[1] - .5)) / 0.16); };
  double mean = 0.0;
  for (uint32_t t = 0; t < 16; ++t) mean += estimate(table_points(t, 1024), f, 0.0, 1.0, g) / 16;
  EXPECT_NEAR(mean, std::numbers::pi * 0.09, 0.01 * std::numbers::pi * 0.09 * 3);
}

TEST(RankThreshold, KeptSubsequenceExtendsWithThePrefix) {
  // Kept points stay in rank order (they are a subsequence of the hierarchy) and a longer
  // prefix keeps more of them.
  auto c = table_points(0, 1024);
  auto f = [](Vec2 p) { return p[1]; };
  RankSelection a = rank_threshold(std::span(c).first(512), f, 0.0, 1.0);
  RankSelection b = rank_threshold(c, f, 0.0, 1.0);
  EXPECT_TRUE(std::is_sorted(a.kept.begin(), a.kept.end()));
  EXPECT_TRUE(std::is_sorted(b.kept.begin(), b.kept.end()));
  EXPECT_GT(b.kept.size(), a.kept.size());
}

}  // namespace
}  // namespace pdrt
