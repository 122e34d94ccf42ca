#pragma once
// Normalised modified Phong about the mirror direction (Lafortune & Willems 1994), the glossy
// material's `lobe: "phong"`: exponent as given, no mapping from roughness.
#include "renderer/render/bxdf/bsdf_sample.h"

namespace pdrt {

struct PhongBxdf {
  static constexpr bool kDelta = false;
  Vec3 albedo{0.0f};
  float exponent = 0.0f;

  Vec3 eval(const Vec3& wo, const Vec3& wi) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;
  static constexpr bool uses_lobe_choice() { return false; }  // one lobe
};

}  // namespace pdrt
