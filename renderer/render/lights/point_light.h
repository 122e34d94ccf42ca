#pragma once
// A point light (a delta light): the one direction to it, I / d^2 (the irradiance at a
// surface facing it, as `radiance` so the integrator's f L |cos| / pdf holds), probability 1.
// The light-family pair u is not used: its values are a pure function of (pixel, sample,
// family, bounce), so leaving it unread shifts no other stream.
#include "renderer/render/lights/light_placement.h"

#include <array>

namespace pdrt {

struct PointLight {
  LightPlacement placement;

  LightBounds bounds() const { return placement.bounds(); }
  bool sample(const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const;
};

}  // namespace pdrt
