#pragma once
// Pixel reconstruction filters (Cook §4.2) and what the three reconstructions need of them:
// a tabulated |f| to draw offsets from (importance), the weight at an offset (splat, rank),
// and the filter's extremes and mean over its square support (rank).
#include "renderer/scene/scene_desc.h"
#include "sampling/core/piecewise_constant.h"

#include <array>

namespace pdrt {

struct FilterSample {
  float x = 0, y = 0;  // offset from the pixel centre, in pixels
  float weight = 0;    // f / pdf: sign(f) * integral |f| up to the table's resolution
};

class Filter {
 public:
  explicit Filter(const FilterDesc& d);
  float radius() const { return radius_; }
  // Weight at offset (x, y) in pixels from the pixel centre; exactly 0 past the radius.
  float eval(float x, float y) const;
  // An offset drawn in proportion to |f| (pbrt-v4's FilterSampler): a piecewise-constant
  // table over the support (the Gaussian's over d^2), so every sample lands where the filter
  // is and all are traced.
  FilterSample sample(std::array<double, 2> u) const;
  // The largest weight (at the centre): rank selection normalises by it (McCool–Fiume §5.2).
  float max_value() const { return max_; }
  // The smallest weight (negative for Mitchell's lobes), found on a fine grid.
  float min_value() const { return min_; }
  // Mean of f over the square [-r, r]^2, and of the rank-keep probability
  // (f - min) / (max - min) there: the fraction of uniform candidates rank selection keeps.
  double mean_value() const { return mean_; }
  double mean_keep() const { return (mean_ - min_) / (double(max_) - min_); }

 private:
  FilterType type_;
  float radius_;
  float max_ = 1, min_ = 0;
  float sigma_ = 0;       // pbrt-v4's separable Gaussian when > 0
  float gauss_tail_ = 0;  // the Gaussian at the radius, subtracted so the filter ends at 0
  double mean_ = 0;
  PiecewiseConstant2D table_;   // |f| over the square
  PiecewiseConstant1D radial_;  // the Gaussian's f over d^2 (empty for the separable filters)
};

}  // namespace pdrt
