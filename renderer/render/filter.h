#pragma once
// Pixel reconstruction filters (Cook §4.2). Each pixel's samples are spread over the filter's
// support around the pixel centre and weighted by the filter; the pixel value is the
// normalised weighted mean (sum w L / sum w). Because a sample only ever contributes to its
// own pixel, images are bit-identical whatever the thread count (pbrt-v4 does the same).
#include "renderer/scene/scene_desc.h"

namespace pdrt {

class Filter {
 public:
  explicit Filter(const FilterDesc& d);
  float radius() const { return radius_; }
  // Weight at offset (x, y) in pixels from the pixel centre; exactly 0 past the radius.
  float eval(float x, float y) const;
  // The largest weight (at the centre): rank selection normalises by it (McCool–Fiume §5.2).
  float max_value() const { return max_; }
  // The smallest weight (negative for Mitchell's lobes), found on a fine grid.
  float min_value() const { return min_; }

 private:
  FilterType type_;
  float radius_;
  float max_ = 1, min_ = 0;
  float gauss_tail_ = 0;
};

}  // namespace pdrt
