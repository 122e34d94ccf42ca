#pragma once
// An emissive sphere: from outside, sampled uniformly over the cone of directions it subtends
// (pbrt-v3 §14.2.2); from inside (or on it), uniformly by area. A moving one where it is at
// the ray's time, by the transform Embree intersects.
#include "renderer/render/light_bounds.h"
#include "renderer/render/lights/area_emitter.h"
#include "renderer/render/lights/light_sample.h"

#include <array>

namespace pdrt {

struct SphereLight {
  AreaEmitter emitter;

  // Box (a moving one's over the shutter), the whole sphere of normals, phi = luminance x
  // pi r^2 (its projected area from any side).
  LightBounds bounds() const;
  bool sample(const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const;
  // pick times the solid-angle pdf that sample() from ref produced the point of `hit`.
  float pdf(const Vec3& ref, const SurfaceHit& hit, float time, float pick) const;

 private:
  bool sample_area(const Affine& m, const Vec3& c, float r, const Vec3& ref, std::array<double, 2> u,
                   LightSample* out) const;
};

}  // namespace pdrt
