#include "renderer/scene/crop_window.h"

#include <cmath>

namespace pdrt {

PixelRect crop_pixels(const std::array<float, 4>& c, int width, int height) {
  const float w = float(width), h = float(height);
  return {int(std::ceil(w * c[0])), int(std::ceil(w * c[1])), int(std::ceil(h * c[2])), int(std::ceil(h * c[3]))};
}

namespace {

// The largest float x in [0, 1] with ceil(size x) == pixel: the quotient, nudged down while
// rounding puts it past the pixel, and up while it falls short.
float ndc_for(int pixel, int size) {
  if (pixel <= 0) return 0;
  if (pixel >= size) return 1;
  float x = float(pixel) / float(size);
  while (std::ceil(float(size) * x) > float(pixel)) x = std::nextafter(x, 0.0f);
  while (std::ceil(float(size) * x) < float(pixel)) x = std::nextafter(x, 1.0f);
  return x;
}

}  // namespace

std::array<float, 4> crop_window_for_pixels(int px0, int px1, int py0, int py1, int width, int height) {
  return {ndc_for(px0, width), ndc_for(px1, width), ndc_for(py0, height), ndc_for(py1, height)};
}

}  // namespace pdrt
