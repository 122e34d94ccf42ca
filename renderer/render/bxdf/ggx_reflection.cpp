#include "renderer/render/bxdf/ggx_reflection.h"

#include "renderer/render/bxdf/ms_mixture.h"
#include "renderer/render/fresnel.h"
#include "renderer/render/ggx_albedo.h"
#include "renderer/render/microfacet_ggx.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

GgxReflectionBxdf GgxReflectionBxdf::glossy(const Vec3& f0, float alpha, bool energy_compensation) {
  GgxReflectionBxdf b;
  b.f0_ = f0;
  b.alpha_ = alpha;
  b.compensate(energy_compensation);
  return b;
}

GgxReflectionBxdf GgxReflectionBxdf::conductor(const Vec3& eta, const Vec3& k, float alpha, bool energy_compensation) {
  GgxReflectionBxdf b;
  b.conductor_ = true;
  b.eta_ = eta, b.k_ = k;
  b.alpha_ = alpha;
  b.compensate(energy_compensation);
  return b;
}

void GgxReflectionBxdf::compensate(bool energy_compensation) {
  if (!energy_compensation) return;
  // Kulla & Conty 2017: f_ms carries 1 - E(mu_o) when F = 1. With Fresnel, the light that
  // does not leave after a bounce (1 - E_avg) is reflected with F_avg and leaves with E_avg
  // at each further bounce: sum_k F_avg^(k+1) E_avg (1 - E_avg)^k = (1 - E_avg) F_ms with
  // F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)). Schlick's F_avg = F0 + (1 - F0) / 21.
  float e_avg = ggx_conductor_albedo_average(alpha_);
  if (!(1.0f - e_avg > 1e-5f)) return;
  ms_ = true;
  row_.e_avg[0] = e_avg;
  row_.nodes = ggx_albedo_nodes(false);
  for (int i = 0; i < row_.nodes; ++i) row_.e[0][i] = ggx_conductor_albedo(float(i) / float(row_.nodes - 1), alpha_);
  Vec3 f_avg = conductor_ ? fresnel_conductor_average(eta_, k_) : f0_ + (Vec3(1.0f) - f0_) * (1.0f / 21.0f);
  Vec3 f_ms = f_avg * f_avg * e_avg / (Vec3(1.0f) - f_avg * (1.0f - e_avg));
  ms_scale_ = f_ms * (kInvPi / (1.0f - e_avg));
  ms_pick_ss_ = (f_avg.x + f_avg.y + f_avg.z) / 3.0f;
  ms_pick_ms_ = (f_ms.x + f_ms.y + f_ms.z) / 3.0f;
}

Vec3 GgxReflectionBxdf::eval(const Vec3& wo, const Vec3& wi) const {
  return ms_ ? eval_ss(wo, wi) + eval_ms(wo, wi) : eval_ss(wo, wi);
}

float GgxReflectionBxdf::pdf(const Vec3& wo, const Vec3& wi) const {
  float ss = pdf_ss(wo, wi);
  if (!ms_) return ss;
  return ms_mixture_pdf(ms_probability(wo), ss, pdf_ms(wo, wi));
}

bool GgxReflectionBxdf::sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const {
  return ms_ ? sample_compensated(wo, u1, u2, uc, out) : sample_ss(wo, u1, u2, out);
}

Vec3 GgxReflectionBxdf::fresnel(float cos_i) const {
  return conductor_ ? fresnel_conductor(cos_i, eta_, k_) : fresnel_schlick(f0_, cos_i);
}

Vec3 GgxReflectionBxdf::eval_ss(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere_up(wo, wi)) return Vec3(0.0f);
  Vec3 h = wo + wi;
  if (dot(h, h) == 0) return Vec3(0.0f);
  h = normalize(h);
  MicrofacetGgx ggx(alpha_);
  // Cook-Torrance / Walter 2007 eq. 20.
  return fresnel(dot(wi, h)) * (ggx.d(h) * ggx.g2(wo, wi) / (4.0f * wo.z * wi.z));
}

float GgxReflectionBxdf::pdf_ss(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere_up(wo, wi)) return 0.0f;
  Vec3 h = wo + wi;
  if (dot(h, h) == 0) return 0.0f;
  h = normalize(h);
  // Visible-normal density times the reflection Jacobian dm/dwi = 1 / (4 wo.m).
  return MicrofacetGgx(alpha_).pdf_visible(wo, h) / (4.0f * dot(wo, h));
}

bool GgxReflectionBxdf::sample_ss(const Vec3& wo, float u1, float u2, BsdfSample* out) const {
  if (wo.z <= 0) return false;
  MicrofacetGgx ggx(alpha_);
  Vec3 m = ggx.sample_visible(wo, u1, u2);
  float c = dot(wo, m);
  if (c <= 0) return false;
  Vec3 wi = reflect(wo, m);
  if (wi.z <= 0) return false;
  out->wi = normalize(wi);
  out->pdf = ggx.pdf_visible(wo, m) / (4.0f * c);
  // f cos / pdf with the visible-normal pdf: D and the Jacobian cancel, G1(wo) remains.
  out->weight = fresnel(c) * (ggx.g2(wo, wi) / ggx.g1(wo));
  return true;
}

float GgxReflectionBxdf::ms_probability(const Vec3& wo) const {
  if (wo.z <= 0) return 0.0f;
  float e = row_.at(wo.z, 0);
  // The lobes carry E F_avg and (1 - E) F_ms (channel means).
  float ss = e * ms_pick_ss_, ms = (1.0f - e) * ms_pick_ms_;
  return ss + ms > 0 ? ms / (ss + ms) : 0.0f;
}

Vec3 GgxReflectionBxdf::eval_ms(const Vec3& wo, const Vec3& wi) const {
  if (!(wo.z > 0) || !(wi.z > 0)) return Vec3(0.0f);
  float lo = 1.0f - row_.at(wo.z, 0);
  return ms_scale_ * (lo * (1.0f - row_.at(wi.z, 0)));
}

float GgxReflectionBxdf::pdf_ms(const Vec3& wo, const Vec3& wi) const {
  return wo.z > 0 && wi.z > 0 ? wi.z * kInvPi : 0.0f;
}

bool GgxReflectionBxdf::sample_compensated(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const {
  if (wo.z <= 0) return false;
  float p = ms_probability(wo);
  if (uc < p) {
    // The compensation lobe: a cosine direction (Malley).
    float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
    float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    if (z <= 0) return false;
    float side = wo.z > 0 ? 1.0f : -1.0f;
    out->wi = {r * std::cos(phi), r * std::sin(phi), side * z};
    return ms_mixture_from_compensation(pdf(wo, out->wi), eval(wo, out->wi), out);
  }
  if (!sample_ss(wo, u1, u2, out)) return false;
  return ms_mixture_from_single(p, pdf_ms(wo, out->wi), eval_ms(wo, out->wi), out);
}

}  // namespace pdrt
