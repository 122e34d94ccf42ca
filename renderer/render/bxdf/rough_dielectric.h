#pragma once
// Rough dielectric interface after Walter et al. 2007 (GGX, alpha = roughness^2): reflection is
// white, transmission tinted by albedo and scaled by 1/eta^2; wo.z > 0 is outside. With energy
// compensation, on side s (0 outside, index 1; 1 inside, index ior) with total (R + T) albedo
// E_s, the lobe
//   reflection   r_s (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (pi (1 - E_avg,s))
//   transmission (1 - r_s) (1 - E_s(mu_o)) (1 - E_s'(mu_i)) / (pi (1 - E_avg,s')) / eta^2
// returns exactly the 1 - E_s(mu_o) that single scattering loses, and the BTDF stays
// reciprocal (rough_dielectric.cpp, RoughDielectricBxdf::make).
#include "renderer/render/bxdf/bsdf_sample.h"
#include "renderer/render/bxdf/ms_albedo_row.h"

namespace pdrt {

class RoughDielectricBxdf {
 public:
  static constexpr bool kDelta = false;
  static RoughDielectricBxdf make(const Vec3& albedo, float alpha, float ior, bool energy_compensation);

  Vec3 eval(const Vec3& wo, const Vec3& wi) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;

 private:
  Vec3 eval_ss(Vec3 wo, Vec3 wi) const;
  float pdf_ss(Vec3 wo, Vec3 wi) const;
  bool sample_ss(Vec3 wo, float u1, float u2, float uc, BsdfSample* out) const;
  float ms_probability(const Vec3& wo) const;  // of choosing the compensation lobe in sample()
  Vec3 eval_ms(const Vec3& wo, const Vec3& wi) const;
  float pdf_ms(const Vec3& wo, const Vec3& wi) const;  // of wi, given that the lobe is chosen
  bool sample_compensated(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;

  Vec3 albedo_{0.0f};
  float alpha_ = 1.0f;
  float ior_ = 1.5f;           // inside / outside
  bool ms_ = false;            // energy compensation active
  MsAlbedoRow row_;            // E per side at this alpha and ior
  float reflect_[2] = {1, 1};  // reflected fraction of the compensation lobe per side
};

}  // namespace pdrt
