#pragma once
// The camera-sample step (pbrt-v4's GetCameraSample): the pixel-filter offset, the shutter
// time and the lens point of one sample, drawn in that order from the pixel's sampler state.
#include "renderer/render/filter.h"
#include "sampling/samplers/sampler.h"

#include <cstdint>

namespace pdrt {

struct CameraSample {
  float film_x = 0, film_y = 0;  // film point in pixels: pixel centre plus the filter offset
  float weight = 0;              // filter weight (divided by the kept density under rank selection)
  float time = 0;                // fraction of the shutter, [0, 1)
  Vec2 lens{};                   // lens sample, [0, 1)^2
};

// How a pixel's samples are filtered: by weight, or (McCool–Fiume §5.2) kept by rank against
// the filter among the pixel's `rank_budget` samples.
struct CameraSampleRule {
  const Filter& filter;
  bool rank_selection = false;
  int rank_budget = 0;
};

// Camera sample `index` of pixel (x, y); starts `ps` on that sample. False when the sample
// is not taken (outside the filter, or not kept by rank); then time and lens are not drawn.
bool get_camera_sample(const CameraSampleRule& rule, int x, int y, int64_t index, PixelSampleState& ps,
                       CameraSample* out);

}  // namespace pdrt
