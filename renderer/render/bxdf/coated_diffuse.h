#pragma once
// The coated_diffuse BSDF: a Lambertian base of reflectance rho (Material::albedo) under a
// dielectric coat of index eta (Material::ior), smooth (a delta reflection) or GGX-rough, with
// an optional absorbing coat. The analytic layered model of Weidlich & Wilkie 2007 as in
// Mitsuba's plastic / roughplastic, written in terms of the coat's directional reflection
// albedo E(mu) (exact Fresnel F(mu) when smooth, the generated table ggx_coat_albedo when rough):
//   f = f_coat(wo, wi)
//     + rho A(mu_o) A(mu_i) (1 - E(mu_o)) (1 - E(mu_i)) / (pi eta^2 (1 - rho F_in T_in))
// 1 - E(mu) enters the coat (rough: everything the single-scattering coat lobe does not
// reflect); 1/eta^2 is the radiance compression at the coat; F_in = 1 - (1 - E_avg) / eta^2 is
// the internal reflectance of diffuse light under the coat (E_avg = 2 int E mu dmu; for the
// smooth coat this identity is exact, Fresnel's reciprocity), and 1 / (1 - rho F_in) sums the
// inter-reflections between base and coat. With rho = 1 and a clear coat, every wo reflects
// E(mu_o) + (1 - E(mu_o)) = 1: energy is conserved exactly on the albedo table, and f is
// symmetric in (wo, wi): reciprocal.
// Absorbing coat (Beer-Lambert): A(mu) = coat_color^(coat_thickness / mu_t), mu_t the cosine
// of the refracted direction (Snell at the macro surface); the inter-reflections are attenuated
// by T_in = coat_color^(4 coat_thickness), a round trip at the mean diffuse path length 2 per
// pass (mean of 1/mu under a cosine lobe), which only lowers the albedo.
// Sampling: the coat lobe (delta reflection, or GGX visible normals) or the base (cosine) with
// probability from their albedos at wo: E(mu_o) against (1 - E(mu_o)) x the base's estimated
// albedo. pdf() is the exact mixture pdf of the non-delta part; a smooth coat's delta sample has
// the discrete probability of its lobe as pdf and `delta` set (not usable for MIS).
#include "renderer/render/bxdf/bsdf_sample.h"
#include "renderer/scene/material.h"
#include "renderer/scene/vec3.h"

namespace pdrt {

class CoatedDiffuse {
 public:
  static constexpr bool kDelta = false;  // a smooth coat's delta reflection sits beside the base
  CoatedDiffuse() = default;
  explicit CoatedDiffuse(const Material& m);

  Vec3 eval(const Vec3& wo, const Vec3& wi) const;  // non-delta part, without the cosine
  float pdf(const Vec3& wo, const Vec3& wi) const;  // non-delta part of the mixture
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;

  bool smooth() const { return smooth_; }
  // E(mu): the white coat's directional reflection albedo (F(mu) when smooth).
  float coat_albedo(float mu) const;
  // Probability that sample() chooses the coat lobe at mu_o = wo.z > 0.
  float coat_probability(float mu_o) const;

 private:
  Vec3 transmittance(float mu) const;  // A(mu), 1 for a clear coat
  Vec3 eval_base(const Vec3& wo, const Vec3& wi) const;
  Vec3 eval_coat(const Vec3& wo, const Vec3& wi) const;  // rough coat only
  float pdf_coat(const Vec3& wo, const Vec3& wi) const;  // rough coat only, given the lobe

  bool smooth_ = true;
  float ior_ = 1.5f;
  float alpha_ = 1.0f;
  bool absorbing_ = false;
  Vec3 depth_{0.0f};       // optical depth of one normal pass: -coat_thickness ln(coat_color)
  Vec3 base_scale_{0.0f};  // rho / (pi eta^2 (1 - rho F_in T_in))
  Vec3 base_pick_{0.0f};   // the base's albedo once light is in: rho (1 - F_in) T / (1 - rho F_in T_in)
  // Rough coat: E(mu) at this alpha and eta on the table's mu nodes, so a lookup is one lerp.
  static constexpr int kNodes = 16;
  float e_row_[kNodes] = {};
};

}  // namespace pdrt
