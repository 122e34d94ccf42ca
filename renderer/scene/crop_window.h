#pragma once
// pbrt-v4's crop window (§5.4.2, RGBFilm/PixelSensor's pixelBounds): the NDC rectangle
// [x0, x1] x [y0, y1] of the film (y down) selects pixels ceil(width x0) .. ceil(width x1) - 1
// and ceil(height y0) .. ceil(height y1) - 1. The crop keeps the full film's camera and sample
// coordinates, so a cropped render is the crop of the full one.
#include <array>

namespace pdrt {

struct PixelRect {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // half-open: [x0, x1) x [y0, y1)
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

// Float arithmetic as pbrt-v4's, so the same window picks the same pixels.
PixelRect crop_pixels(const std::array<float, 4>& crop, int width, int height);

// The NDC window whose crop_pixels are exactly [px0, px1) x [py0, py1) (pbrt-v4's
// "pixelbounds"); the rectangle must lie within the film.
std::array<float, 4> crop_window_for_pixels(int px0, int px1, int py0, int py1, int width, int height);

}  // namespace pdrt
