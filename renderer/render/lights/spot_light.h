#pragma once
// A spot light (a delta light): a point light whose intensity falls off from the cone's
// falloff start to its edge by pbrt-v4's smoothstep, and is 0 past it. Sampled as the point
// light (point_light.h), times the falloff.
#include "renderer/render/lights/light_placement.h"

#include <array>

namespace pdrt {

struct SpotLight {
  LightPlacement placement;

  // The point light's bounds plus its cone: normals within the falloff start, emission
  // reaching the cone's edge (plus 1e-3 rad of slop for the rounding of the importance's
  // angles, so a point just inside the cone never gets importance 0). A moving one keeps the
  // whole sphere of normals, since it may turn.
  LightBounds bounds() const;
  bool sample(const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const;
};

}  // namespace pdrt
