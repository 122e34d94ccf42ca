#include "renderer/render/lights/environment_light.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

// The importance is in the BVH's units (irradiance): a constant radiance L over the
// hemisphere on either side of n delivers E = pi L; an image, pi times its mean luminance
// over the sphere. No scene-size term: the lights' importance falls with distance, the
// environment's does not.
EnvironmentLight::EnvironmentLight(const EnvironmentDesc& d, EnvironmentSampling sampling) {
  if (d.has_map()) {
    map = std::make_shared<const EnvironmentMap>(d.width, d.height, d.rgb, d.scale, d.rotation_deg, sampling);
    irradiance = map->irradiance_estimate();
  } else {
    constant = d.radiance;
    if (!is_black(constant)) irradiance = kPi * std::max(luminance(constant), 1e-6f);
  }
}

bool EnvironmentLight::sample(const Vec3&, float, std::array<double, 2> u, LightSample* out) const {
  out->dist = 1e30f;
  out->at_infinity = true;
  if (has_image()) return map->sample(u, &out->wi, &out->radiance, &out->pdf);
  // Uniform over the sphere of directions.
  float z = float(1 - 2 * u[0]), r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = float(2 * kPi * u[1]);
  out->wi = {r * std::cos(phi), r * std::sin(phi), z};
  out->radiance = constant;
  out->pdf = 1.0f / (4 * kPi);
  return true;
}

}  // namespace pdrt
