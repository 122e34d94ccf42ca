#pragma once
// A world-space ray with the shutter time it samples (normalised to [0,1) over the shutter).
#include "renderer/scene/vec3.h"

namespace pdrt {

struct Ray {
  Vec3 org, dir;
  float tmin = 0, tmax = 1e30f;
  float time = 0;
};

}  // namespace pdrt
