#include "renderer/render/bxdf/rough_dielectric.h"

#include "renderer/render/bxdf/ms_mixture.h"
#include "renderer/render/fresnel.h"
#include "renderer/render/ggx_albedo.h"
#include "renderer/render/microfacet_ggx.h"

#include <algorithm>
#include <cmath>

namespace pdrt {
namespace {

// The microfacet normal that refracts wo (upper side) into wi (lower side) for relative index eta:
// the generalised half vector of Walter 2007 eq. 16, oriented up. In double, with wo and wi
// renormalised: at grazing wo.m, 1 - F depends steeply on wo.m, and a float's 1e-7 error in
// |w| would otherwise break Snell's law at m by 1e-4 and with it reciprocity.
struct Refraction {
  Vec3 m;
  double wo_m, wi_m;  // wo_m > 0 > wi_m
};
bool refraction_normal(const Vec3& wo, const Vec3& wi, double eta, Refraction* r) {
  double o[3], i[3], h[3], lo = 0, li = 0, len2 = 0;
  for (int k = 0; k < 3; ++k) lo += double(wo[k]) * wo[k], li += double(wi[k]) * wi[k];
  lo = std::sqrt(lo), li = std::sqrt(li);
  for (int k = 0; k < 3; ++k) {
    o[k] = wo[k] / lo, i[k] = wi[k] / li;
    h[k] = o[k] + eta * i[k], len2 += h[k] * h[k];
  }
  if (len2 == 0) return false;
  double s = (h[2] < 0 ? -1.0 : 1.0) / std::sqrt(len2);
  r->wo_m = r->wi_m = 0;
  for (int k = 0; k < 3; ++k) h[k] *= s, r->wo_m += o[k] * h[k], r->wi_m += i[k] * h[k];
  r->m = {float(h[0]), float(h[1]), float(h[2])};
  return r->wo_m > 0 && r->wi_m < 0;
}

}  // namespace

RoughDielectricBxdf RoughDielectricBxdf::make(const Vec3& albedo, float alpha, float ior, bool energy_compensation) {
  RoughDielectricBxdf b;
  b.albedo_ = albedo;
  b.alpha_ = alpha;
  b.ior_ = ior;
  if (!energy_compensation) return b;
  // The reflection is symmetric; the BTDF obeys f(o -> i) ior^2 = f(i -> o) (Veach 1997 §5.2)
  // when (1 - r_s)(1 - E_avg,s) n_s^2 is the same on both sides (n_s the side's index). r is the
  // smooth interface's average Fresnel reflectance on the side entering the denser medium; the
  // other side's r follows (clamped to [0, 1], where reciprocity would be lost).
  MsAlbedoRow& row = b.row_;
  row.e_avg[0] = ggx_dielectric_albedo_average(alpha, ior);
  row.e_avg[1] = ggx_dielectric_albedo_average(alpha, 1.0f / ior);
  if (!(std::min(1.0f - row.e_avg[0], 1.0f - row.e_avg[1]) > 1e-5f)) return b;
  b.ms_ = true;
  row.nodes = ggx_albedo_nodes(true);
  for (int i = 0; i < row.nodes; ++i)
    for (int side = 0; side < 2; ++side)
      row.e[side][i] = ggx_dielectric_albedo(float(i) / float(row.nodes - 1), alpha, side == 0 ? ior : 1.0f / ior);
  int rare = ior >= 1 ? 0 : 1, dense = 1 - rare;
  float n2[2] = {1.0f, ior * ior};
  b.reflect_[rare] = float(fresnel_dielectric_average(rare == 0 ? ior : 1.0 / ior));
  float tau = (1.0f - b.reflect_[rare]) * (1.0f - row.e_avg[rare]) * n2[rare];
  b.reflect_[dense] = std::clamp(1.0f - tau / ((1.0f - row.e_avg[dense]) * n2[dense]), 0.0f, 1.0f);
  return b;
}

Vec3 RoughDielectricBxdf::eval(const Vec3& wo, const Vec3& wi) const {
  return ms_ ? eval_ss(wo, wi) + eval_ms(wo, wi) : eval_ss(wo, wi);
}

float RoughDielectricBxdf::pdf(const Vec3& wo, const Vec3& wi) const {
  float ss = pdf_ss(wo, wi);
  if (!ms_) return ss;
  return ms_mixture_pdf(ms_probability(wo), ss, pdf_ms(wo, wi));
}

bool RoughDielectricBxdf::sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const {
  return ms_ ? sample_compensated(wo, u1, u2, uc, out) : sample_ss(wo, u1, u2, uc, out);
}

// Evaluated with wo flipped to the upper side: the microfacet distribution is symmetric about
// the macro surface, so looking from inside is looking from outside at an interface of
// relative index 1 / ior.

Vec3 RoughDielectricBxdf::eval_ss(Vec3 wo, Vec3 wi) const {
  if (wo.z == 0 || wi.z == 0) return Vec3(0.0f);
  double eta = ior_;  // double: 1 / ior in float alone moves Snell's law at grazing m by 1e-4
  if (wo.z < 0) wo.z = -wo.z, wi.z = -wi.z, eta = 1.0 / ior_;
  MicrofacetGgx ggx(alpha_);
  if (wi.z > 0) {
    Vec3 h = wo + wi;
    if (dot(h, h) == 0) return Vec3(0.0f);
    h = normalize(h);
    return Vec3(ggx.d(h) * ggx.g2(wo, wi) * float(fresnel_dielectric(dot(wo, h), eta)) / (4.0f * wo.z * wi.z));
  }
  Refraction r;
  if (!refraction_normal(wo, wi, eta, &r)) return Vec3(0.0f);
  double denom = r.wo_m + eta * r.wi_m;
  double t = 1.0 - fresnel_dielectric(r.wo_m, eta);
  // Walter eq. 21 for radiance: the eta_o^2 factor is 1 on the side of wo.
  double g = double(ggx.d(r.m)) * ggx.g2(wo, wi) * t * -r.wo_m * r.wi_m / (double(wo.z) * -wi.z * denom * denom);
  return albedo_ * float(g);
}

float RoughDielectricBxdf::pdf_ss(Vec3 wo, Vec3 wi) const {
  if (wo.z == 0 || wi.z == 0) return 0.0f;
  double eta = ior_;  // double: 1 / ior in float alone moves Snell's law at grazing m by 1e-4
  if (wo.z < 0) wo.z = -wo.z, wi.z = -wi.z, eta = 1.0 / ior_;
  MicrofacetGgx ggx(alpha_);
  if (wi.z > 0) {
    Vec3 h = wo + wi;
    if (dot(h, h) == 0) return 0.0f;
    h = normalize(h);
    float ho = dot(wo, h);
    return ggx.pdf_visible(wo, h) * float(fresnel_dielectric(ho, eta)) / (4.0f * ho);
  }
  Refraction r;
  if (!refraction_normal(wo, wi, eta, &r)) return 0.0f;
  double denom = r.wo_m + eta * r.wi_m;
  // Refraction Jacobian dm/dwi = eta^2 |wi.m| / (wo.m + eta wi.m)^2 (Walter eq. 17).
  double t = 1.0 - fresnel_dielectric(r.wo_m, eta);
  return float(ggx.pdf_visible(wo, r.m) * t * eta * eta * -r.wi_m / (denom * denom));
}

bool RoughDielectricBxdf::sample_ss(Vec3 wo, float u1, float u2, float uc, BsdfSample* out) const {
  if (wo.z == 0) return false;
  bool inside = wo.z < 0;
  float eta = ior_;
  if (inside) wo.z = -wo.z, eta = 1.0f / ior_;
  MicrofacetGgx ggx(alpha_);
  Vec3 m = ggx.sample_visible(wo, u1, u2);
  float ho = dot(wo, m);
  if (ho <= 0) return false;
  double f = fresnel_dielectric(ho, eta);
  float pm = ggx.pdf_visible(wo, m);
  Vec3 wi;
  if (uc < f) {
    wi = normalize(reflect(wo, m));
    if (wi.z <= 0) return false;
    out->pdf = float(pm * f / (4.0f * ho));
    out->weight = Vec3(ggx.g2(wo, wi) / ggx.g1(wo));
  } else {
    if (!refract(wo, m, eta, &wi)) return false;
    wi = normalize(wi);
    if (wi.z >= 0) return false;
    float hi = dot(wi, m);
    float denom = ho + eta * hi;
    out->pdf = float(pm * (1.0 - f) * eta * eta * -hi / (denom * denom));
    out->weight = albedo_ * (ggx.g2(wo, wi) / (ggx.g1(wo) * eta * eta));
    out->transmission = true;
    out->eta = eta;
  }
  if (inside) wi.z = -wi.z;
  out->wi = wi;
  return true;
}

// ---- Multiple-scattering compensation.

float RoughDielectricBxdf::ms_probability(const Vec3& wo) const {
  if (wo.z == 0) return 0.0f;
  // The two lobes carry E and 1 - E of a white furnace.
  return 1.0f - row_.at(std::abs(wo.z), wo.z > 0 ? 0 : 1);
}

Vec3 RoughDielectricBxdf::eval_ms(const Vec3& wo, const Vec3& wi) const {
  if (wo.z == 0 || wi.z == 0) return Vec3(0.0f);
  int so = wo.z > 0 ? 0 : 1, si = wi.z > 0 ? 0 : 1;
  float lo = 1.0f - row_.at(std::abs(wo.z), so);
  float li = (1.0f - row_.at(std::abs(wi.z), si)) / (kPi * (1.0f - row_.e_avg[si]));
  if (so == si) return Vec3(reflect_[so] * lo * li);
  float eta = so == 0 ? ior_ : 1.0f / ior_;
  return albedo_ * ((1.0f - reflect_[so]) * lo * li / (eta * eta));
}

float RoughDielectricBxdf::pdf_ms(const Vec3& wo, const Vec3& wi) const {
  if (wo.z == 0 || wi.z == 0) return 0.0f;
  bool same = (wo.z > 0) == (wi.z > 0);
  float r = reflect_[wo.z > 0 ? 0 : 1];
  return (same ? r : 1.0f - r) * std::abs(wi.z) * kInvPi;
}

bool RoughDielectricBxdf::sample_compensated(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const {
  if (wo.z == 0) return false;
  const float one_minus = 0x1.fffffep-1f;
  float p = ms_probability(wo);
  if (uc < p) {
    // The compensation lobe: reflect or transmit, then a cosine direction on that side (Malley).
    float v = std::min(uc / p, one_minus);
    bool transmit = v >= reflect_[wo.z > 0 ? 0 : 1];
    float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
    float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    if (z <= 0) return false;
    float side = (wo.z > 0) != transmit ? 1.0f : -1.0f;
    out->wi = {r * std::cos(phi), r * std::sin(phi), side * z};
    out->transmission = transmit;
    out->eta = transmit ? (wo.z > 0 ? ior_ : 1.0f / ior_) : 1.0f;
    return ms_mixture_from_compensation(pdf(wo, out->wi), eval(wo, out->wi), out);
  }
  float v = std::min((uc - p) / (1.0f - p), one_minus);
  if (!sample_ss(wo, u1, u2, v, out)) return false;
  return ms_mixture_from_single(p, pdf_ms(wo, out->wi), eval_ms(wo, out->wi), out);
}

}  // namespace pdrt
