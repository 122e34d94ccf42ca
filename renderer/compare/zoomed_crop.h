#pragma once
// Crops of an image drawn enlarged into a display-RGB canvas: the report's detail crops and the
// demonstration sheet's cells.
#include "renderer/image/image.h"
#include "renderer/image/image_output.h"
#include "renderer/scene/vec3.h"

#include <cstddef>
#include <vector>

namespace pdrt {

// The display (sRGB) colour of `im`'s pixel (x, y).
inline Vec3 srgb_pixel(const Image& im, int x, int y) {
  const std::size_t i = 3 * (std::size_t(y) * im.width + x);
  return Vec3(linear_to_srgb(im.rgb[i]), linear_to_srgb(im.rgb[i + 1]), linear_to_srgb(im.rgb[i + 2]));
}

// value(cx, cy) of every pixel of a side x side crop, each as a zoom x zoom block, into `rgb`
// (a canvas `width` pixels wide) with the crop's top left at (x0, y0).
template <class F>
void paste_zoomed(std::vector<float>& rgb, int width, int x0, int y0, int side, int zoom, const F& value) {
  for (int y = 0; y < side * zoom; ++y)
    for (int x = 0; x < side * zoom; ++x) {
      const Vec3 c = value(x / zoom, y / zoom);
      const std::size_t i = 3 * (std::size_t(y0 + y) * width + x0 + x);
      rgb[i] = c.x, rgb[i + 1] = c.y, rgb[i + 2] = c.z;
    }
}

}  // namespace pdrt
