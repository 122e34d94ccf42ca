#pragma once
// Smooth dielectric interface: delta reflection or refraction chosen by exact Fresnel.
// Reflection is white, transmission tinted by albedo and scaled by 1/eta^2 (camera-path
// radiance transport, as pbrt-v4's TransportMode::Radiance); wo.z > 0 is outside. An index of 1
// (also with roughness) is an invisible interface, a pure pass-through.
#include "renderer/render/bxdf/bsdf_sample.h"

namespace pdrt {

struct SmoothDielectricBxdf {
  static constexpr bool kDelta = true;
  Vec3 albedo{0.0f};
  float ior = 1.5f;  // inside / outside

  Vec3 eval(const Vec3&, const Vec3&) const { return Vec3(0.0f); }
  float pdf(const Vec3&, const Vec3&) const { return 0.0f; }
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;
  static constexpr bool uses_direction() { return false; }  // reflect or refract: uc alone
};

}  // namespace pdrt
