#pragma once
// Importance sampling by rank threshold (McCool & Fiume §5.2, "ordered dithering"): from a
// hierarchical prefix s_1..s_n keep s_i when rank(s_i) = i/n <= x(s_i), where
// x = (f - min f) / (max f - min f). Kept points have density proportional to x, and the kept
// subsequence is still a prefix-extendable hierarchy.
//
// Estimator: a point at s is kept with probability x(s) (its rank is uniform and
// independent of its position), so  I = ∫ g  ≈  (1/n) Σ_kept g(s_i) / x(s_i),  unbiased
// where x > 0 on g's support. When ∫ x over the domain (volume 1) is known in closed form,
// the self-normalised form  I ≈ (∫x / k) Σ_kept g/x  (k = kept count) has lower variance; the
// plain form estimates ∫x from the same table as k/n. See docs/sampling.md.
#include "sampling/samplers/sampler.h"

#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace pdrt {

struct RankSelection {
  std::vector<uint32_t> kept;  // indices into the candidate prefix, in rank order
  std::vector<double> weight;  // per kept point: multiply g(s) by it and sum to estimate ∫g
  double x_integral = 0.0;     // ∫x used (closed form, or k/n estimated from the table)
};

// `f_min`/`f_max` bound f over the domain (the normalisation of §5.2); `x_integral`, when
// known, is ∫ (f - f_min)/(f_max - f_min) over the unit domain.
RankSelection rank_threshold(std::span<const Vec2> candidates, const std::function<double(Vec2)>& f, double f_min,
                             double f_max, std::optional<double> x_integral = std::nullopt);

}  // namespace pdrt
