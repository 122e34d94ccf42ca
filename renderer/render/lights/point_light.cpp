#include "renderer/render/lights/point_light.h"

namespace pdrt {

bool PointLight::sample(const Vec3& ref, float time, std::array<double, 2>, LightSample* out) const {
  Vec3 p;
  placement.at(time, &p, nullptr);
  float d2;
  if (!aim_at_point(p, ref, out, &d2)) return false;
  out->radiance = placement.desc->intensity * (1.0f / d2);
  return true;
}

}  // namespace pdrt
