#include "renderer/render/lights/spot_light.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace {

// pbrt-v4's SmoothStep: 0 at x <= a, 1 at x >= b, a cubic between (a step when a == b).
float smoothstep(float x, float a, float b) {
  if (a == b) return x < a ? 0.0f : 1.0f;
  const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

}  // namespace

LightBounds SpotLight::bounds() const {
  LightBounds b = placement.bounds();
  const DeltaLightDesc& l = *placement.desc;
  if (!l.motion.empty()) return b;
  Vec3 p, axis;
  placement.at(0, &p, &axis);
  if (is_finite(axis)) {
    const float start = std::acos(std::clamp(l.cos_falloff_start, -1.0f, 1.0f));
    const float end = std::acos(std::clamp(l.cos_cone, -1.0f, 1.0f));
    b.normals = {axis, l.cos_falloff_start};
    b.cos_e = std::cos(std::min(kPi, end - start + 1e-3f));
  }
  return b;
}

bool SpotLight::sample(const Vec3& ref, float time, std::array<double, 2>, LightSample* out) const {
  const DeltaLightDesc& l = *placement.desc;
  Vec3 p, axis;
  placement.at(time, &p, &axis);
  float d2;
  if (!is_finite(axis) || !aim_at_point(p, ref, out, &d2)) return false;
  const float falloff = smoothstep(-dot(axis, out->wi), l.cos_cone, l.cos_falloff_start);
  out->radiance = l.intensity * (falloff / d2);
  return true;
}

}  // namespace pdrt
