#pragma once
// What a light's sample() returns: the direction toward a point on the light (or toward the
// light at infinity), the radiance arriving along it, and its solid-angle pdf.
#include "renderer/render/ray_spawn.h"
#include "renderer/scene/vec3.h"

namespace pdrt {

struct LightSample {
  Vec3 wi;                   // unit direction from the reference point to the light
  float dist = 0;            // distance to the sampled point (1e30 for the environment)
  bool at_infinity = false;  // the environment, a distant light: no point to aim the shadow ray at
  bool delta = false;        // a point, spot or distant light: no MIS (weight 1); pdf is the pick probability
  ErrorPoint x;              // the sampled point on an area light, with its error bound (shadow rays end there)
  Vec3 n;                    // the light's geometric normal at x
  Vec3 radiance;             // emitted radiance toward the reference point (0 if back-facing)
  float pdf = 0;             // solid-angle pdf (times the choice of this light, once LightSet has chosen it)
};

}  // namespace pdrt
