#include "renderer/render/bxdf/coated_diffuse.h"

#include "renderer/render/fresnel.h"
#include "renderer/render/ggx_albedo.h"
#include "renderer/render/ggx_albedo_tables.h"
#include "renderer/render/microfacet_ggx.h"

#include <algorithm>
#include <cmath>

namespace pdrt {
namespace {

float mean(const Vec3& v) { return (v.x + v.y + v.z) / 3.0f; }

Vec3 exp_neg(const Vec3& v) { return {std::exp(-v.x), std::exp(-v.y), std::exp(-v.z)}; }

}  // namespace

CoatedDiffuse::CoatedDiffuse(const Material& m)
    : smooth_(!(m.roughness > 0)),
      // The loader refuses other indices; the coat table holds this range, and below 1 the
      // coat would reflect totally from outside.
      ior_(std::clamp(m.ior, 1.0f, ggx_tables::kEtaMax)),
      alpha_(std::max(kMinGgxAlpha, m.roughness * m.roughness)) {
  static_assert(kNodes == ggx_tables::kDielMu, "e_row_ holds one row of the coat table");
  float e_avg;
  if (smooth_) {
    e_avg = float(fresnel_dielectric_average_closed(ior_));
  } else {
    for (int i = 0; i < kNodes; ++i) e_row_[i] = ggx_coat_albedo(float(i) / float(kNodes - 1), alpha_, ior_);
    e_avg = ggx_coat_albedo_average(alpha_, ior_);
  }
  // Optical depth of one pass at normal incidence; a black coat (ln 0) is infinitely deep.
  for (int c = 0; c < 3; ++c) {
    float col = m.coat_color[c];
    depth_[c] = col >= 1.0f || m.coat_thickness <= 0 ? 0.0f : col <= 0 ? INFINITY : -m.coat_thickness * std::log(col);
  }
  absorbing_ = max_component(depth_) > 0;
  const float eta2 = ior_ * ior_;
  const float f_in = 1.0f - (1.0f - e_avg) / eta2;
  const Vec3 t_pass = exp_neg(depth_ * 2.0f), t_in = t_pass * t_pass;
  for (int c = 0; c < 3; ++c) {
    float rho = m.albedo[c], series = 1.0f / (1.0f - rho * f_in * t_in[c]);
    base_scale_[c] = rho * series * kInvPi / eta2;
    base_pick_[c] = rho * (1.0f - f_in) * t_pass[c] * series;
  }
}

float CoatedDiffuse::coat_albedo(float mu) const {
  if (smooth_) return float(fresnel_dielectric(mu, ior_));
  // The table is linear in mu between its nodes, so this equals the full lookup.
  float g = std::clamp(mu, 0.0f, 1.0f) * float(kNodes - 1);
  int i = std::min(int(g), kNodes - 2);
  return std::clamp(e_row_[i] + (e_row_[i + 1] - e_row_[i]) * (g - float(i)), 0.0f, 1.0f);
}

Vec3 CoatedDiffuse::transmittance(float mu) const {
  if (!absorbing_) return Vec3(1.0f);
  // The refracted cosine (Snell at the macro surface); > 0 for ior > 1, kept > 0 for ior = 1.
  float mu_t = std::sqrt(std::max(0.0f, 1.0f - (1.0f - mu * mu) / (ior_ * ior_)));
  return exp_neg(depth_ / std::max(mu_t, 1e-6f));
}

float CoatedDiffuse::coat_probability(float mu_o) const {
  float e = coat_albedo(mu_o);
  float base = (1.0f - e) * mean(transmittance(mu_o) * base_pick_);
  return e + base > 0 ? e / (e + base) : 1.0f;
}

Vec3 CoatedDiffuse::eval_base(const Vec3& wo, const Vec3& wi) const {
  float t = (1.0f - coat_albedo(wo.z)) * (1.0f - coat_albedo(wi.z));
  Vec3 f = base_scale_ * t;
  return absorbing_ ? f * transmittance(wo.z) * transmittance(wi.z) : f;
}

Vec3 CoatedDiffuse::eval_coat(const Vec3& wo, const Vec3& wi) const {
  Vec3 h = wo + wi;
  if (dot(h, h) == 0) return Vec3(0.0f);
  h = normalize(h);
  MicrofacetGgx ggx(alpha_);
  // Walter 2007 eq. 20 with the exact dielectric Fresnel; white, as a clear coat's reflection.
  float f = float(fresnel_dielectric(dot(wo, h), ior_));
  return Vec3(f * ggx.d(h) * ggx.g2(wo, wi) / (4.0f * wo.z * wi.z));
}

float CoatedDiffuse::pdf_coat(const Vec3& wo, const Vec3& wi) const {
  Vec3 h = wo + wi;
  if (dot(h, h) == 0) return 0.0f;
  h = normalize(h);
  // Visible normals times the reflection Jacobian 1 / (4 wo.m).
  return MicrofacetGgx(alpha_).pdf_visible(wo, h) / (4.0f * dot(wo, h));
}

Vec3 CoatedDiffuse::eval(const Vec3& wo, const Vec3& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return Vec3(0.0f);
  Vec3 f = eval_base(wo, wi);
  return smooth_ ? f : f + eval_coat(wo, wi);
}

float CoatedDiffuse::pdf(const Vec3& wo, const Vec3& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0.0f;
  float p = coat_probability(wo.z);
  float base = (1.0f - p) * wi.z * kInvPi;
  return smooth_ ? base : base + p * pdf_coat(wo, wi);
}

bool CoatedDiffuse::sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const {
  *out = BsdfSample{};
  if (wo.z <= 0) return false;
  float p = coat_probability(wo.z);
  Vec3 wi;
  if (uc < p) {
    if (smooth_) {
      // The delta reflection: F(mu_o) cos / cos over the choice probability.
      out->wi = {-wo.x, -wo.y, wo.z};
      out->pdf = p;
      out->delta = true;
      out->weight = Vec3(coat_albedo(wo.z) / p);
      return true;
    }
    MicrofacetGgx ggx(alpha_);
    Vec3 m = ggx.sample_visible(wo, u1, u2);
    if (dot(wo, m) <= 0) return false;
    wi = reflect(wo, m);
    if (wi.z <= 0) return false;
    wi = normalize(wi);
  } else {
    // The base: cosine-weighted (Malley's method).
    float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
    float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    if (z <= 0) return false;
    wi = {r * std::cos(phi), r * std::sin(phi), z};
  }
  // One-sample mixture: the weight is the whole f cos over the whole pdf, the pdf MIS sees.
  out->wi = wi;
  out->pdf = pdf(wo, wi);
  if (!(out->pdf > 0)) return false;
  out->weight = eval(wo, wi) * (wi.z / out->pdf);
  return true;
}

}  // namespace pdrt
