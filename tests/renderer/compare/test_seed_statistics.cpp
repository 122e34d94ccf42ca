// compare's statistics over seeds: the MSE split into bias^2 and variance, the reference's
// variance from two halves, and the 95 % interval of the mean RMSE.
#include "renderer/compare/seed_statistics.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace pdrt;

namespace {
Image blank(int w, int h) {
  Image im;
  im.width = w, im.height = h;
  im.rgb.assign(std::size_t(3) * w * h, 0.0f);
  return im;
}

// truth + offset + N(0, sigma^2) in every pixel channel.
Image noisy(const Image& truth, double offset, double sigma, Rng& rng) {
  Image im = truth;
  for (float& v : im.rgb) v = float(v + offset + sigma * rng.normal());
  return im;
}

Image truth_image(int w, int h) {
  Image im = blank(w, h);
  Rng rng(7);
  for (float& v : im.rgb) v = float(rng.uniform());
  return im;
}
}  // namespace

TEST(SeedStatistics, ImageAgainstItselfHasZeroBiasAndVariance) {
  Image a = truth_image(16, 12);
  SeedStatistics s = seed_statistics({a, a, a, a}, a, ReferenceNoise{});
  EXPECT_EQ(s.bias2, 0.0);
  EXPECT_EQ(s.variance, 0.0);
  EXPECT_EQ(s.rmse_mean, 0.0);
  EXPECT_EQ(s.rmse_ci95, 0.0);
  EXPECT_EQ(reference_noise(a, 8, a, 8).variance, 0.0);
  EXPECT_EQ(reference_noise(a, 8, a, 8).correction_se, 0.0);
}

// x_k = I + b + N(0, s^2) against an exact reference: bias^2 -> b^2, variance -> s^2, and the
// mean MSE is their sum exactly.
TEST(SeedStatistics, SplitsAConstantOffsetFromTheNoise) {
  Image truth = truth_image(64, 64);
  Rng rng(11);
  std::vector<Image> seeds;
  for (int k = 0; k < 8; ++k) seeds.push_back(noisy(truth, 0.03, 0.05, rng));
  SeedStatistics s = seed_statistics(seeds, truth, ReferenceNoise{});
  std::printf("bias2 %.6g (0.0009), variance %.6g (0.0025)\n", s.bias2, s.variance);
  EXPECT_NEAR(s.bias2, 0.03 * 0.03, 0.05 * 0.0009);
  EXPECT_NEAR(s.variance, 0.05 * 0.05, 0.03 * 0.0025);
  EXPECT_NEAR(s.mse_mean, s.bias2 + s.variance, 1e-12);
}

// Two halves of N(0, 2 t^2) each give a reference of variance t^2; unequal halves weigh in.
TEST(SeedStatistics, HalfReferencesMeasureTheReferenceVariance) {
  Image truth = truth_image(64, 64);
  Rng rng(13);
  const double t = 0.02;
  Image a = noisy(truth, 0, t * std::sqrt(2.0), rng), b = noisy(truth, 0, t * std::sqrt(2.0), rng);
  EXPECT_NEAR(reference_noise(a, 100, b, 100).variance, t * t, 0.04 * t * t);
  // na = 3 nb: Var(a) = s^2 / 3, Var(b) = s^2, reference variance s^2 / 4.
  Image c = noisy(truth, 0, 0.01, rng), d = noisy(truth, 0, 0.01 * std::sqrt(3.0), rng);
  EXPECT_NEAR(reference_noise(c, 300, d, 100).variance, 0.01 * 0.01 * 3 / 4, 0.04 * 0.01 * 0.01 * 3 / 4);
}

TEST(SeedStatistics, StudentQuantileMatchesTables) {
  EXPECT_NEAR(student_t95(1), 12.7062, 1e-4);
  EXPECT_NEAR(student_t95(3), 3.18245, 1e-4);
  EXPECT_NEAR(student_t95(40), 2.02108, 1e-4);
  EXPECT_NEAR(student_t95(120), 1.97993, 1e-4);
}

// Known truth: images I + N(0, s^2), a reference from two noisy halves (variance (s/2)^2, as
// at the smallest allowed --reference-spp of 4x the spp), K seeds. The true RMSE is s; over
// 2000 trials the 95 % interval must cover it about 95 % of the time (binomial sd 0.49 %).
// The root-sum-square of the two parts' half widths is slightly conservative (measured 95.7 %
// at K = 16 to 96.9 % at K = 3); Welch-Satterthwaite's effective degrees of freedom were
// liberal instead (88.9 % at K = 2, 93.6 % at K = 4), and leaving the reference's part out
// gave 91.8 % at K = 4.
static double coverage_of_true_rmse(int K, uint64_t seed, double* mean_rmse) {
  const int trials = 2000;
  const double s = 0.05, t = s / 2;
  Image truth = truth_image(24, 16);
  Rng rng(seed);
  int covered = 0;
  *mean_rmse = 0;
  for (int i = 0; i < trials; ++i) {
    Image a = noisy(truth, 0, t * std::sqrt(2.0), rng), b = noisy(truth, 0, t * std::sqrt(2.0), rng);
    Image ref = a;
    for (std::size_t j = 0; j < ref.rgb.size(); ++j) ref.rgb[j] = 0.5f * (a.rgb[j] + b.rgb[j]);
    std::vector<Image> seeds;
    for (int k = 0; k < K; ++k) seeds.push_back(noisy(truth, 0, s, rng));
    SeedStatistics st = seed_statistics(seeds, ref, reference_noise(a, 1, b, 1));
    covered += std::abs(st.rmse_mean - s) <= st.rmse_ci95;
    *mean_rmse += st.rmse_mean / (trials * s);
  }
  return double(covered) / trials;
}

TEST(SeedStatistics, ConfidenceIntervalCoversTheTrueRmse) {
  for (int K : {2, 4}) {
    double mean_rmse = 0;
    const double coverage = coverage_of_true_rmse(K, 17 + K, &mean_rmse);
    std::printf("K = %d: coverage %.4f, mean RMSE / true %.5f\n", K, coverage, mean_rmse);
    EXPECT_GE(coverage, 0.935) << K;
    EXPECT_LE(coverage, 0.975) << K;
    EXPECT_NEAR(mean_rmse, 1.0, 0.002) << "the reference's variance must be taken out";
  }
}

// A per-seed measure's mean and the seeds' part of its interval: t(0.975, 3) s / sqrt(4) for
// 1, 2, 3, 4 (s = sqrt(5/3)); one seed has no interval.
TEST(SeedStatistics, SeedMeanIsTheMeanWithItsStudentInterval) {
  const SeedMean m = seed_mean({1, 2, 3, 4});
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_NEAR(m.ci95, 3.18245 * std::sqrt(5.0 / 3.0) / 2, 1e-9);
  EXPECT_EQ(seed_mean({0.7}).ci95, 0.0);
}
