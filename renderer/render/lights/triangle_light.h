#pragma once
// One triangle of an emissive mesh, sampled uniformly by area (square-root map of the
// barycentrics); a moving one where it is at the ray's time, by the transform Embree
// intersects. Diffuse emission from its front face (both with `two_sided`).
#include "renderer/render/light_bounds.h"
#include "renderer/render/lights/area_emitter.h"
#include "renderer/render/lights/light_sample.h"

#include <array>

namespace pdrt {

struct TriangleLight {
  AreaEmitter emitter;
  int prim = 0;  // the triangle's index in the shape

  // Box (a moving one's over the shutter), normal cone (a moving one's the whole sphere:
  // it may turn), phi = luminance x area.
  LightBounds bounds() const;
  bool sample(const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const;
  // pick times the solid-angle pdf that sample() from ref produced the point of `hit`.
  float pdf(const Vec3& ref, const SurfaceHit& hit, float time, float pick) const;

 private:
  // World-space corners at the normalised shutter time.
  void corners(float time, Vec3* a, Vec3* b, Vec3* c) const;
  // The point at barycentrics (b1, b2), built where the geometry is stored (instance space
  // for a moving shape) so its error bound includes the transform's.
  ErrorPoint point_at(float time, float b1, float b2) const;
};

}  // namespace pdrt
