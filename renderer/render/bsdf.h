#pragma once
// The BSDF a Material describes, in the local shading frame (normal = +z). wo points away
// from the surface, toward the viewer; wi toward the light. Opaque materials reflect only when
// wo.z > 0 and wi.z > 0; dielectrics treat wo.z > 0 as outside and scale transmitted radiance by
// 1/eta^2 (camera-path radiance transport, as pbrt-v4's TransportMode::Radiance).
//   Diffuse     Lambert, cosine-weighted sampling.
//   Glossy      GGX: Schlick Fresnel with F0 = albedo, alpha = roughness^2, height-correlated
//               Smith G2, visible-normal sampling. Phong: normalised modified Phong about the
//               mirror direction, exponent as given (no mapping from roughness).
//   Conductor   exact conductor Fresnel with complex index eta + ik per RGB channel
//               (fresnel_conductor): roughness 0 a delta reflection, otherwise the GGX lobe of
//               Glossy with that Fresnel in place of Schlick's (pbrt-v4's ConductorBxDF).
//   Mirror      delta reflection weighted by Schlick Fresnel with F0 = albedo.
//   Dielectric  roughness 0: delta reflection / refraction chosen by exact Fresnel; otherwise
//               Walter et al. 2007 GGX. Reflection is white, transmission tinted by albedo.
//   ThinDielectric  pbrt-v4's ThinDielectricBxDF: a slab so thin that light leaves where it
//               entered. Both faces' Fresnel reflectance R and all inner bounces sum to
//               R' = R + T^2 R / (1 - R^2), T' = 1 - R' (T = 1 - R): delta reflection, or delta
//               transmission straight through (wi = -wo, no refraction, no 1/eta^2), tinted by
//               albedo as the dielectric's transmission is. Two-sided: wo.z < 0 works the same.
//   CoatedDiffuse  Lambert base (albedo) under a smooth (delta) or GGX-rough dielectric coat,
//               optionally absorbing (coated_diffuse.h): Weidlich & Wilkie 2007's layered
//               model on the coat's albedo, energy conserving and reciprocal. A smooth coat is
//               one delta lobe beside a non-delta one: is_delta() is false, eval() and pdf()
//               give the non-delta part, sample() flags the delta reflection.
// Energy compensation (Material::energy_compensation, on by default): single-scattering GGX
// loses the light that bounces more than once between microfacets (31 % kept at roughness 1).
// A diffuse-like multiple-scattering lobe built on the albedo tables of ggx_albedo.h returns it:
//   GGX glossy  Kulla & Conty 2017: f_ms = (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg)),
//               times F_avg^2 E_avg / (1 - F_avg (1 - E_avg)) for coloured F0.
//   Dielectric  the same shape on each side with the total (R + T) albedo E_s of that side,
//               split into reflection and transmission so that every side conserves energy and
//               the BTDF stays reciprocal (see bsdf.cpp, Bsdf::Bsdf).
// The lobe is sampled as a cosine lobe, chosen with a probability from the lobes' albedos.
#include "renderer/render/coated_diffuse.h"
#include "renderer/scene/material.h"
#include "renderer/scene/vec3.h"

namespace pdrt {

struct BsdfSample {
  Vec3 wi;             // local shading frame (normal = +z), unit length
  Vec3 weight;         // f(wo, wi) |cos wi| / pdf: the path-throughput factor
  float pdf = 0;       // solid-angle pdf of wi (for a delta lobe: the discrete probability of that lobe)
  bool delta = false;  // chosen lobe is a Dirac delta (mirror / smooth dielectric): not usable for MIS
  bool transmission = false;
  float eta = 1;       // transmitted over incident index for transmission, else 1 (radiance scales by 1/eta^2)
};

class Bsdf {
 public:
  explicit Bsdf(const Material& m);  // Emitter (and unresolved Mix) material -> a black, non-scattering BSDF

  Vec3 eval(const Vec3& wo, const Vec3& wi) const;  // f(wo, wi), without the cosine; 0 for delta lobes
  float pdf(const Vec3& wo, const Vec3& wi) const;  // solid-angle pdf that sample() produces wi (non-delta part)
  // u1, u2 in [0, 1) choose the direction, uc in [0, 1) the lobe (Fresnel reflect vs transmit).
  // False when no direction is produced (below the horizon, wo grazing, non-scattering).
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;

  bool is_delta() const;  // every lobe is a delta (mirror, conductor or dielectric with roughness 0, thin dielectric)
  bool scatters() const;  // false for emitters
  Vec3 albedo() const;    // for the albedo AOV

 private:
  enum class Kind {
    Black, Lambert, Ggx, Phong, Mirror, SmoothConductor, SmoothDielectric, RoughDielectric, Coated, ThinDielectric
  };

  Vec3 fresnel_ggx(float cos_i) const;  // Schlick with F0 = albedo, or the exact conductor Fresnel
  Vec3 eval_ggx(const Vec3& wo, const Vec3& wi) const;
  float pdf_ggx(const Vec3& wo, const Vec3& wi) const;
  bool sample_ggx(const Vec3& wo, float u1, float u2, BsdfSample* out) const;
  Vec3 eval_rough_dielectric(Vec3 wo, Vec3 wi) const;
  float pdf_rough_dielectric(Vec3 wo, Vec3 wi) const;
  bool sample_rough_dielectric(Vec3 wo, float u1, float u2, float uc, BsdfSample* out) const;
  bool sample_smooth_dielectric(Vec3 wo, float uc, BsdfSample* out) const;
  bool sample_thin_dielectric(Vec3 wo, float uc, BsdfSample* out) const;

  // Multiple-scattering compensation (ms_ on): side 0 is wo.z > 0, 1 below (dielectrics only).
  float ms_albedo(float mu, int side) const;       // E of the single-scattering lobe
  float ms_probability(const Vec3& wo) const;      // of choosing the compensation lobe in sample()
  Vec3 eval_ms(const Vec3& wo, const Vec3& wi) const;
  float pdf_ms(const Vec3& wo, const Vec3& wi) const;  // of wi, given that the lobe is chosen
  bool sample_compensated(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;

  Kind kind_ = Kind::Black;
  Vec3 albedo_{0.0f};
  float alpha_ = 1.0f;     // GGX roughness, alpha = roughness^2 clamped to >= kMinGgxAlpha
  float exponent_ = 0.0f;  // Phong
  float ior_ = 1.5f;       // inside / outside
  bool conductor_ = false; // Ggx / SmoothConductor: exact complex Fresnel with eta_, k_
  Vec3 eta_{1.0f}, k_{0.0f};
  bool ms_ = false;        // energy compensation active
  Vec3 ms_scale_{0.0f};    // conductor: F_ms / (pi (1 - E_avg)) per channel
  float ms_pick_ss_ = 0, ms_pick_ms_ = 0;  // conductor: mean F_avg and F_ms, weights of the lobe choice
  float e_avg_[2] = {1, 1};  // E_avg per side (the conductor uses side 0)
  // E(mu) per side at this alpha (and eta) on the tables' mu nodes, so that a lookup is one lerp.
  static constexpr int kMsNodes = 32;
  float e_row_[2][kMsNodes] = {};
  int e_nodes_ = kMsNodes;
  float reflect_[2] = {1, 1};  // dielectric: reflected fraction of the compensation lobe per side
  CoatedDiffuse coated_;       // Kind::Coated
};

// A thin dielectric slab's reflectance at |cos| = cos_i (pbrt-v4 §9.5.1): the first face's
// Fresnel R plus everything the inner bounces send back, R + T^2 R / (1 - R^2). Its
// transmittance is 1 minus this.
double thin_dielectric_reflectance(double cos_i, double ior);

// Smallest GGX alpha: keeps rough lobes non-delta and their D finite in float.
inline constexpr float kMinGgxAlpha = 1e-3f;

// Path regularisation (IntegratorDesc::regularize; Kaplanyan & Dachsbacher 2013, as pbrt-v4's
// `regularize` option does it): the material a vertex shades with once the path has scattered
// off a non-delta lobe. A GGX alpha below 0.3 becomes clamp(2 alpha, 0.1, 0.3) (glossy,
// conductor, dielectric and the coated_diffuse coat; roughness 0 counts as alpha 0, so smooth
// ones become rough at alpha 0.1); a mirror becomes the GGX glossy of its F0 at alpha 0.1; a
// Phong lobe gets the exponent of that alpha (n = 2 / alpha^2 - 2, Walter et al. 2007). Diffuse,
// thin dielectric (whose transmission keeps its direction), emitter and mix materials are
// unchanged. Biased: near-specular caustics blur; never on unless asked.
Material regularized(const Material& m);
inline constexpr float kRegularizeAlphaMax = 0.3f;
inline constexpr float kRegularizeAlphaMin = 0.1f;

}  // namespace pdrt
