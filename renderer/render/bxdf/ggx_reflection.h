#pragma once
// GGX microfacet reflection: the glossy material (Schlick Fresnel with F0 = albedo) and the
// rough conductor (exact conductor Fresnel, pbrt-v4's ConductorBxDF). alpha = roughness^2,
// height-correlated Smith G2, visible-normal sampling. With energy compensation, Kulla & Conty
// 2017's lobe f_ms = (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg)), times
// F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) for coloured F0, sampled as a cosine lobe chosen with
// a probability from the lobes' albedos.
#include "renderer/render/bxdf/bsdf_sample.h"
#include "renderer/render/bxdf/ms_albedo_row.h"

namespace pdrt {

class GgxReflectionBxdf {
 public:
  static constexpr bool kDelta = false;
  static GgxReflectionBxdf glossy(const Vec3& f0, float alpha, bool energy_compensation);
  static GgxReflectionBxdf conductor(const Vec3& eta, const Vec3& k, float alpha, bool energy_compensation);

  Vec3 eval(const Vec3& wo, const Vec3& wi) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;
  bool uses_lobe_choice() const { return ms_; }  // the compensation lobe or the single-scattering one

 private:
  void compensate(bool energy_compensation);
  Vec3 fresnel(float cos_i) const;  // Schlick with F0 = f0_, or the exact conductor Fresnel
  Vec3 eval_ss(const Vec3& wo, const Vec3& wi) const;
  float pdf_ss(const Vec3& wo, const Vec3& wi) const;
  bool sample_ss(const Vec3& wo, float u1, float u2, BsdfSample* out) const;
  float ms_probability(const Vec3& wo) const;  // of choosing the compensation lobe in sample()
  Vec3 eval_ms(const Vec3& wo, const Vec3& wi) const;
  float pdf_ms(const Vec3& wo, const Vec3& wi) const;  // of wi, given that the lobe is chosen
  bool sample_compensated(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;

  Vec3 f0_{0.0f};
  float alpha_ = 1.0f;
  bool conductor_ = false;
  Vec3 eta_{1.0f}, k_{0.0f};
  bool ms_ = false;                        // energy compensation active
  Vec3 ms_scale_{0.0f};                    // F_ms / (pi (1 - E_avg)) per channel
  float ms_pick_ss_ = 0, ms_pick_ms_ = 0;  // mean F_avg and F_ms, weights of the lobe choice
  MsAlbedoRow row_;                        // side 0 only
};

}  // namespace pdrt
