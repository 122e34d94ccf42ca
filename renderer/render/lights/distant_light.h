#pragma once
// A distant light (a delta light at infinity): one direction, its irradiance E as
// `radiance`, probability 1. Beside the light BVH, its importance at a point of normal n is
// the irradiance luminance(E) |cos| it delivers there.
#include "renderer/render/light_bounds.h"
#include "renderer/render/lights/light_sample.h"

#include <array>

namespace pdrt {

struct DistantLight {
  Vec3 to_light;  // unit, against the direction the light travels
  Vec3 irradiance;
  float lum = 0;  // luminance of the irradiance (> 0)

  InfiniteLightBounds bounds() const { return {to_light, lum, true}; }
  bool sample(const Vec3&, float, std::array<double, 2>, LightSample* out) const {
    out->wi = to_light;
    out->dist = 1e30f;
    out->at_infinity = true;
    out->delta = true;
    out->radiance = irradiance;
    out->pdf = 1;
    return true;
  }
};

}  // namespace pdrt
