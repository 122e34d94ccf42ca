#pragma once
// Lambertian reflection (the diffuse material), sampled cosine-weighted by Malley's method.
#include "renderer/render/bxdf/bsdf_sample.h"

namespace pdrt {

struct LambertBxdf {
  static constexpr bool kDelta = false;
  Vec3 albedo{0.0f};

  Vec3 eval(const Vec3& wo, const Vec3& wi) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;
  static constexpr bool uses_lobe_choice() { return false; }  // one lobe
};

}  // namespace pdrt
