#pragma once
// The camera-sample step (pbrt-v4's GetCameraSample): the film point, the shutter time and
// the lens point of one sample, drawn in that order from the pixel's sampler state.
#include "renderer/render/filter.h"
#include "sampling/samplers/sampler.h"

#include <cstdint>

namespace pdrt {

struct CameraSample {
  float film_x = 0, film_y = 0;  // film point in pixels
  float weight = 0;              // the sample's weight in its own pixel (1 under splatting)
  float time = 0;                // fraction of the shutter, [0, 1)
  Vec2 lens{};                   // lens sample, [0, 1)^2
};

// How a pixel's samples become film points (FilterDesc::reconstruction). Under rank selection
// a pixel's budget of n samples is n / mean_keep() candidates, so that n are traced on average;
// `rank_candidates` are those of the prefix being completed, `rank_candidates_before` those of
// the prefix already taken (0 when none): a candidate is taken when it is kept against the
// first and was not against the second.
struct CameraSampleRule {
  const Filter& filter;
  Reconstruction mode = Reconstruction::Importance;
  double rank_candidates = 0, rank_candidates_before = 0;
  bool lens = true;  // false: a pinhole camera, whose rays ignore the lens point (not drawn)
  bool time = true;  // false: a scene where nothing moves, whose rays ignore the time (not drawn)
};

// Candidates a rank-selected prefix of `spp` samples ranks against.
double rank_candidates(const Filter& filter, int64_t spp);

// Camera sample `index` of pixel (x, y); starts `ps` on that sample. False when the sample
// is not taken (only under rank selection); then time and lens are not drawn.
bool get_camera_sample(const CameraSampleRule& rule, int x, int y, int64_t index, PixelSampleState& ps,
                       CameraSample* out);

}  // namespace pdrt
