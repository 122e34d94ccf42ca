// McCool–Fiume §5.2 importance by rank threshold, on the default lens tables.
#include "sampling/analysis/incomplete_gamma.h"
#include "sampling/samplers/poisson_sampler.h"
#include "sampling/samplers/rank_threshold.h"

#include <gtest/gtest.h>

#include <algorithm>
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
    RankSelection s = rank_threshold(
        c, [](Vec2 p) { return p[0]; }, 0.0, 1.0);
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

TEST(RankThreshold, SelfNormalisedPhongLobeEstimateMatchesItsIntegral) {
  // Uniform hemisphere map z = u, phi = 2 pi v (d omega = 2 pi du dv): the normalised lobe
  // (e+1)/(2 pi) z^e integrates to 1 in closed form. The importance is a wider lobe, f = z^(e/2)
  // with ∫x = 2/(e+2), so g/x is not constant and the estimate depends on which points are kept
  // and how they are weighted. Tolerance: 4 standard errors of the mean over the 16 tables.
  const double e = 20.0;
  auto f = [e](Vec2 p) { return std::pow(p[0], e / 2); };
  auto g = [e](Vec2 p) { return (e + 1) / (2 * std::numbers::pi) * std::pow(p[0], e) * 2 * std::numbers::pi; };
  double sum = 0.0, sum2 = 0.0;
  for (uint32_t t = 0; t < 16; ++t) {
    double v = estimate(table_points(t, 1024), f, 0.0, 1.0, g, 2.0 / (e + 2));
    sum += v, sum2 += v * v;
  }
  const double mean = sum / 16, se = std::sqrt((sum2 / 16 - mean * mean) / 15);
  EXPECT_GT(se, 0.0);  // the kept set matters
  EXPECT_LT(se, 0.02);
  EXPECT_NEAR(mean, 1.0, 4 * se) << "standard error " << se;
}

TEST(RankThreshold, PlainPhongLobeEstimateMatchesItsIntegral) {
  // Without ∫x the weights are 1/(n x): (1/n) Σ_kept g/x, unbiased for the lobe's integral 1.
  const double e = 20.0;
  auto f = [e](Vec2 p) { return std::pow(p[0], e); };
  auto g = [e, f](Vec2 p) { return (e + 1) / (2 * std::numbers::pi) * f(p) * 2 * std::numbers::pi; };
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

// The definition, by brute force: candidate i of n is kept when (i + 1) / n <= x.
std::vector<uint32_t> kept_by_definition(std::span<const Vec2> c, const std::function<double(Vec2)>& f) {
  std::vector<uint32_t> kept;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (double(i + 1) / double(c.size()) <= f(c[i])) kept.push_back(uint32_t(i));
  return kept;
}

bool contains_all(const std::vector<uint32_t>& big, const std::vector<uint32_t>& small) {
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

TEST(RankThreshold, KeptSetOfAPrefixStaysKeptInTheLongerPrefix) {
  // Ranks i/n fall as n grows, so every point kept from the first 512 candidates is kept from
  // all 1024 too (the kept subsequence extends), and both are the brute-force kept sets.
  auto c = table_points(0, 1024);
  auto f = [](Vec2 p) { return p[1]; };
  RankSelection a = rank_threshold(std::span(c).first(512), f, 0.0, 1.0);
  RankSelection b = rank_threshold(c, f, 0.0, 1.0);
  EXPECT_EQ(a.kept, kept_by_definition(std::span(c).first(512), f));
  EXPECT_EQ(b.kept, kept_by_definition(c, f));
  EXPECT_TRUE(contains_all(b.kept, a.kept));
  EXPECT_GT(b.kept.size(), a.kept.size());
}

TEST(RankThreshold, KeptSetGrowsWithTheImportance) {
  // sqrt(y) >= y everywhere: the kept set under sqrt(y) contains the one under y, and each
  // keeps about n ∫x of the candidates (1/2 and 2/3), as the brute-force definition does.
  for (uint32_t t : {0u, 7u}) {
    auto c = table_points(t, 1024);
    auto low = [](Vec2 p) { return p[1]; };
    auto high = [](Vec2 p) { return std::sqrt(p[1]); };
    RankSelection a = rank_threshold(c, low, 0.0, 1.0), b = rank_threshold(c, high, 0.0, 1.0);
    EXPECT_EQ(a.kept, kept_by_definition(c, low)) << t;
    EXPECT_EQ(b.kept, kept_by_definition(c, high)) << t;
    EXPECT_TRUE(contains_all(b.kept, a.kept)) << t;
    EXPECT_NEAR(double(a.kept.size()) / 1024, 0.5, 0.03) << t;
    EXPECT_NEAR(double(b.kept.size()) / 1024, 2.0 / 3.0, 0.03) << t;
  }
}

}  // namespace
}  // namespace pdrt
