#include "renderer/render/screen_window.h"

#include <cmath>

namespace pdrt {

std::array<float, 4> screen_window(const CameraDesc& c, int width, int height) {
  if (c.has_screen_window) return c.screen_window;
  const float half = c.projection == CameraDesc::Projection::Orthographic ? 0.5f * c.ortho_height
                                                                          : std::tan(0.5f * c.vfov_deg * kPi / 180.0f);
  const float half_x = half * (float(width) / float(height));
  return {-half_x, half_x, -half, half};
}

}  // namespace pdrt
