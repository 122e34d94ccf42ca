#pragma once
// Small RGB images for the image-metric tests (renderer/compare/).
#include "renderer/render/film.h"
#include "sampling/core/rng.h"

#include <cstdint>

namespace pdrt::test {

// Every channel of every pixel uniform in [lo, hi), from Rng(seed).
inline Image random_image(int w, int h, uint64_t seed, double lo, double hi) {
  Image im;
  im.width = w, im.height = h;
  Rng rng(seed);
  for (int i = 0; i < 3 * w * h; ++i) im.rgb.push_back(float(lo + (hi - lo) * rng.uniform()));
  return im;
}

// Every pixel (r, g, b).
inline Image flat_image(int w, int h, float r, float g, float b) {
  Image im;
  im.width = w, im.height = h;
  for (int i = 0; i < w * h; ++i) im.rgb.insert(im.rgb.end(), {r, g, b});
  return im;
}

}  // namespace pdrt::test
