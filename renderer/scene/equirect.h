#pragma once
// The equirectangular (latitude-longitude) parameterisation of environment images
// (pbrt-v3 §14.2.4's lat-long map, turned to pdrt's +y up): (u, v) in [0, 1]^2, u along a
// row left to right, v down the image. Row 0 (v = 0) is the zenith +y, the last row the
// nadir -y; the image centre (0.5, 0.5) is -z, the direction the default camera looks, and u
// grows toward +x (to the right as seen from inside): u = 0.75 is +x, u = 0.25 is -x, the
// left and right edges are +z. theta = pi v from +y, phi = 2 pi (u - 0.5) from -z toward +x.
#include "renderer/scene/vec3.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace pdrt {

inline Vec3 equirect_direction(double u, double v) {
  const double theta = M_PI * v, phi = 2 * M_PI * (u - 0.5);
  const double s = std::sin(theta);
  return {float(s * std::sin(phi)), float(std::cos(theta)), float(-s * std::cos(phi))};
}

// (u, v) of the unit direction d, u in [0, 1).
inline std::array<double, 2> equirect_uv(const Vec3& d) {
  const double theta = std::acos(std::clamp(double(d.y), -1.0, 1.0));
  double u = std::atan2(double(d.x), -double(d.z)) / (2 * M_PI) + 0.5;
  if (u >= 1) u -= 1;
  if (u < 0) u = 0;
  return {u, theta / M_PI};
}

// sin(theta) of the unit direction d: the Jacobian (u, v) -> direction is 2 pi^2 sin(theta).
inline double equirect_sin_theta(const Vec3& d) { return std::sqrt(std::max(0.0, 1.0 - double(d.y) * double(d.y))); }

}  // namespace pdrt
