#pragma once
// What point and spot lights share: where the light is at a time (its transform, animated by
// its keyframes over the shutter), its bounds as a point emitter, and the one direction a
// sample of it takes.
#include "renderer/render/light_bounds.h"
#include "renderer/render/lights/light_sample.h"
#include "renderer/scene/scene_desc.h"

namespace pdrt {

struct LightPlacement {
  const DeltaLightDesc* desc = nullptr;       // the scene's
  float shutter_open = 0, shutter_close = 1;  // the camera's: time is normalised to the shutter

  // World position and (if `axis`) unit axis at the normalised time.
  void at(float time, Vec3* p, Vec3* axis) const;
  // A point emitter into every direction: a point box (a moving one's over the shutter), the
  // whole sphere of normals, phi = luminance of I, so that phi cos / d^2 is the irradiance
  // I cos / d^2 it delivers (the BVH's units; pbrt-v4's phi is the power 4 pi I).
  LightBounds bounds() const;
};

// The sample toward the light at p from ref: one direction, probability 1, and no geometry
// there (the shadow ray ends 1e-4 of its length short of p). Sets d2 to the squared
// distance; false when p is at ref or too far for float.
bool aim_at_point(const Vec3& p, const Vec3& ref, LightSample* out, float* d2);

}  // namespace pdrt
