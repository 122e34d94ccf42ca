#include "renderer/render/lights/light_placement.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

void LightPlacement::at(float time, Vec3* p, Vec3* axis) const {
  const DeltaLightDesc& l = *desc;
  Affine m = l.transform;
  if (!l.motion.empty()) {
    const float t = shutter_open + time * (shutter_close - shutter_open);
    m = interpolate(l.motion.data(), int(l.motion.size()), t).matrix() * l.transform;
  }
  *p = m.point(l.position);
  if (axis) *axis = normalize(m.vector(l.direction));
}

LightBounds LightPlacement::bounds() const {
  LightBounds b;
  b.phi = std::max(luminance(desc->intensity), 1e-6f);
  b.cos_e = 0;
  b.normals = DirectionCone{};
  if (desc->motion.empty()) {
    Vec3 p;
    at(0, &p, nullptr);
    b.box.extend(p);
    return b;
  }
  float step = 0;
  Vec3 prev;
  for (int k = 0; k < kTimeSamples; ++k) {
    Vec3 p;
    at(float(k) / (kTimeSamples - 1), &p, nullptr);
    b.box.extend(p);
    if (k > 0) step = std::max(step, length(p - prev));
    prev = p;
  }
  b.box.lo -= Vec3(step), b.box.hi += Vec3(step);
  return b;
}

bool aim_at_point(const Vec3& p, const Vec3& ref, LightSample* out, float* d2) {
  const Vec3 d = p - ref;
  *d2 = dot(d, d);
  if (!(*d2 > 0 && std::isfinite(*d2))) return false;
  const float dist = std::sqrt(*d2);
  out->wi = d / dist, out->dist = dist;
  out->x = {p, Vec3(0.0f)};
  out->n = -out->wi;
  out->delta = true;
  out->pdf = 1;
  return true;
}

}  // namespace pdrt
