#pragma once
// The filter weight a splatting pixel expects per unit density of samples: the integral of its
// filter over the part of the image it covers. A sampler whose pixels take varying counts
// (Sampler::pixel_counts_vary, `poisson-ip`) normalises a pixel by spp times it, not by the sum
// of the weights it received: E[sum w L] = spp * integral of f L over the image, so the estimate
// is unbiased over seeds for the filtered image that a sum-normalised splat converges to, the
// border pixels included (their filters are cut at the image's edge, where samples stop).
#include "renderer/render/filter.h"

#include <vector>

namespace pdrt {

class ExpectedSplatWeight {
 public:
  // Midpoint rule on a grid of 1/64 pixel whose lines hold the pixel borders, so the image's
  // edges cut cells exactly; a summed-area table gives every pixel's rectangle in O(1).
  ExpectedSplatWeight(const Filter& filter, int image_width, int image_height);
  // The integral over the image of pixel (x, y)'s filter, in pixel areas (image pixels).
  double at(int x, int y) const;

 private:
  int half_ = 0;  // the grid spans the pixels within `half_` of the centre pixel, [-half_ - 1/2, half_ + 1/2]
  int side_ = 0;  // grid cells per side
  int width_, height_;
  std::vector<double> sat_;  // (side_ + 1)^2 summed-area table of f times the cell area
};

}  // namespace pdrt
