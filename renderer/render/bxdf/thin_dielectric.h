#pragma once
// pbrt-v4's ThinDielectricBxDF: a slab so thin that light leaves where it entered. Both faces'
// Fresnel reflectance R and all inner bounces sum to R' = R + T^2 R / (1 - R^2), T' = 1 - R'
// (T = 1 - R): delta reflection, or delta transmission straight through (wi = -wo, no
// refraction, no 1/eta^2), tinted by albedo as the dielectric's transmission is. Two-sided:
// wo.z < 0 works the same.
#include "renderer/render/bxdf/bsdf_sample.h"

namespace pdrt {

struct ThinDielectricBxdf {
  static constexpr bool kDelta = true;
  Vec3 albedo{0.0f};
  float ior = 1.5f;

  Vec3 eval(const Vec3&, const Vec3&) const { return Vec3(0.0f); }
  float pdf(const Vec3&, const Vec3&) const { return 0.0f; }
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;
  static constexpr bool uses_direction() { return false; }  // reflect or refract: uc alone
};

// A thin dielectric slab's reflectance at |cos| = cos_i (pbrt-v4 §9.5.1): the first face's
// Fresnel R plus everything the inner bounces send back, R + T^2 R / (1 - R^2). Its
// transmittance is 1 minus this.
double thin_dielectric_reflectance(double cos_i, double ior);

}  // namespace pdrt
