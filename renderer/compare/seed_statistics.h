#pragma once
// Statistics over K renders of one (sampler, spp) with independent seeds, against a reference
// whose own noise is known: per-seed MSE, the mean RMSE with a Student-t 95 % confidence
// interval, and the split MSE = bias^2 + variance. Every MSE has the reference's variance
// subtracted, since E[(x - r)^2] = E[(x - I)^2] + Var(r) for a reference r independent of x.
#include "renderer/render/film.h"

#include <cstdint>
#include <vector>

namespace pdrt {

// Seed k of a comparison: k = 0 is the scene's own seed (so --seeds 1 is the single render of
// earlier versions), k >= 1 a mix64 of (seed, k).
uint64_t compare_seed(uint64_t scene_seed, int k);

// The noise of the reference (na a + nb b) / (na + nb), made of two independent half
// references of na and nb samples per pixel.
struct ReferenceNoise {
  // Averaged over pixels and channels: per pixel E[(a - b)^2] = s^2 (1/na + 1/nb) and
  // Var(reference) = s^2 / (na + nb), so mean((a - b)^2) na nb / (na + nb)^2.
  double variance = 0;
  // Standard error of what subtracting `variance` leaves in every MSE: one reference serves all
  // seeds, so this error is common to them and the seeds' spread does not show it. For equal
  // halves with symmetric noise the left-over term, mean((a - I)(b - I)), has twice the
  // variance of the per-pixel terms d_i = (a_i - b_i)^2 / 4: sqrt(2) sd(d_i) / sqrt(N).
  double correction_se = 0;
};
ReferenceNoise reference_noise(const Image& a, int na, const Image& b, int nb);

// The two-sided 95 % Student-t quantile t_{0.975, dof} (dof >= 1).
double student_t95(int dof);

struct SeedStatistics {
  std::vector<double> mse;   // per seed, mean over pixels and channels of (x_k - r)^2 - noise.variance
  std::vector<double> rmse;  // per seed, sqrt(max(0, mse))
  double rmse_mean = 0;
  // Half width: sqrt((t_{0.975, K-1} s / sqrt(K))^2 + (z_{0.975} correction_se / (2 rmse_mean))^2),
  // the seeds' spread s and the reference's common error carried to the RMSE (delta method);
  // for K = 1 only the latter.
  double rmse_ci95 = 0;
  double mse_mean = 0;  // mean of mse = bias2 + variance
  double variance = 0;  // across seeds, per pixel (K - 1 denominator), averaged over the image; 0 for K = 1
  double bias2 = 0;     // mean((x_bar - r)^2) - variance / K - noise.variance (unbiased; may be < 0 by noise)
};

// A per-seed scalar's mean over the K seeds and the half width of its 95 % interval,
// t_{0.975, K-1} s / sqrt(K) (s the seeds' spread; 0 for K = 1), as the seeds' part of rmse_ci95.
// Measures with no reference correction (the low-frequency share, FLIP) use it.
struct SeedMean {
  double mean = 0, ci95 = 0;
};
SeedMean seed_mean(const std::vector<double>& per_seed);

// `seeds` all the size of `reference`; at least one.
SeedStatistics seed_statistics(const std::vector<Image>& seeds, const Image& reference, const ReferenceNoise& noise);

}  // namespace pdrt
