#pragma once
// Shirley–Chiu (1997) concentric map from the square to the unit disk: area-preserving and
// continuous, so it keeps the stratification of a lens or filter pattern.
#include "renderer/scene/vec3.h"

#include <array>
#include <cmath>

namespace pdrt {

// (r, phi) with the disk point r (cos phi, sin phi) for u in [0, 1)^2; r is signed, and r^2 is
// uniform in [0, 1).
inline std::array<float, 2> concentric_disk_polar(std::array<double, 2> u) {
  float a = float(2 * u[0] - 1), b = float(2 * u[1] - 1);
  if (a == 0 && b == 0) return {0, 0};
  if (std::abs(a) > std::abs(b)) return {a, (kPi / 4) * (b / a)};
  return {b, kPi / 2 - (kPi / 4) * (a / b)};
}

}  // namespace pdrt
