#include "renderer/render/bsdf.h"

#include "renderer/render/fresnel.h"
#include "renderer/render/ggx_albedo.h"
#include "renderer/render/ggx_albedo_tables.h"
#include "renderer/render/microfacet_ggx.h"

#include <algorithm>
#include <cmath>

namespace pdrt {
namespace {

bool same_hemisphere_up(const Vec3& wo, const Vec3& wi) { return wo.z > 0 && wi.z > 0; }

Vec3 mirror_z(const Vec3& w) { return {-w.x, -w.y, w.z}; }

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

Bsdf::Bsdf(const Material& m) : albedo_(m.albedo) {
  static_assert(ggx_tables::kMu <= kMsNodes && ggx_tables::kDielMu <= kMsNodes, "e_row_ holds a table row");
  float alpha = std::max(kMinGgxAlpha, m.roughness * m.roughness);
  switch (m.type) {
    case MaterialType::Emitter:
    case MaterialType::Mix:  // resolved to a component per hit (mix_material.h) before a Bsdf is built
      kind_ = Kind::Black;
      albedo_ = Vec3(0.0f);
      break;
    case MaterialType::Diffuse:
      kind_ = Kind::Lambert;
      break;
    case MaterialType::Glossy:
      kind_ = m.lobe == GlossLobe::Phong ? Kind::Phong : Kind::Ggx;
      alpha_ = alpha;
      exponent_ = std::max(0.0f, m.exponent);
      [[fallthrough]];
    case MaterialType::Conductor:
      if (m.type == MaterialType::Conductor) {
        conductor_ = true;
        eta_ = m.eta, k_ = m.k;
        alpha_ = alpha;
        kind_ = m.roughness > 0 ? Kind::Ggx : Kind::SmoothConductor;
        albedo_ = fresnel_conductor(1.0f, eta_, k_);  // the albedo AOV: normal-incidence reflectance
      }
      if (kind_ == Kind::Ggx && m.energy_compensation) {
        // Kulla & Conty 2017: f_ms carries 1 - E(mu_o) when F = 1. With Fresnel, the light that
        // does not leave after a bounce (1 - E_avg) is reflected with F_avg and leaves with E_avg
        // at each further bounce: sum_k F_avg^(k+1) E_avg (1 - E_avg)^k = (1 - E_avg) F_ms with
        // F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)). Schlick's F_avg = F0 + (1 - F0) / 21.
        float e_avg = ggx_conductor_albedo_average(alpha_);
        if (1.0f - e_avg > 1e-5f) {
          ms_ = true;
          e_avg_[0] = e_avg;
          e_nodes_ = ggx_albedo_nodes(false);
          for (int i = 0; i < e_nodes_; ++i) e_row_[0][i] = ggx_conductor_albedo(float(i) / float(e_nodes_ - 1), alpha_);
          Vec3 f_avg = conductor_ ? fresnel_conductor_average(eta_, k_) : albedo_ + (Vec3(1.0f) - albedo_) * (1.0f / 21.0f);
          Vec3 f_ms = f_avg * f_avg * e_avg / (Vec3(1.0f) - f_avg * (1.0f - e_avg));
          ms_scale_ = f_ms * (kInvPi / (1.0f - e_avg));
          ms_pick_ss_ = (f_avg.x + f_avg.y + f_avg.z) / 3.0f;
          ms_pick_ms_ = (f_ms.x + f_ms.y + f_ms.z) / 3.0f;
        }
      }
      break;
    case MaterialType::Mirror:
      kind_ = Kind::Mirror;
      break;
    case MaterialType::ThinDielectric:
      kind_ = Kind::ThinDielectric;
      ior_ = m.ior;
      break;
    case MaterialType::CoatedDiffuse:
      kind_ = Kind::Coated;
      coated_ = CoatedDiffuse(m);
      break;
    case MaterialType::Dielectric:
      // Index-matched: the interface is invisible, a pure pass-through (delta).
      kind_ = m.roughness > 0 && m.ior != 1.0f ? Kind::RoughDielectric : Kind::SmoothDielectric;
      alpha_ = alpha;
      ior_ = m.ior;
      if (kind_ == Kind::RoughDielectric && m.energy_compensation) {
        // On side s (0 outside, index 1; 1 inside, index ior) with total albedo E_s, the lobe
        //   reflection   r_s (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (pi (1 - E_avg,s))
        //   transmission (1 - r_s) (1 - E_s(mu_o)) (1 - E_s'(mu_i)) / (pi (1 - E_avg,s')) / eta^2
        // returns exactly the 1 - E_s(mu_o) that single scattering loses. The reflection is
        // symmetric; the BTDF obeys f(o -> i) ior^2 = f(i -> o) (Veach 1997 §5.2) when
        // (1 - r_s)(1 - E_avg,s) n_s^2 is the same on both sides (n_s the side's index). r is the
        // smooth interface's average Fresnel reflectance on the side entering the denser medium;
        // the other side's r follows (clamped to [0, 1], where reciprocity would be lost).
        e_avg_[0] = ggx_dielectric_albedo_average(alpha_, ior_);
        e_avg_[1] = ggx_dielectric_albedo_average(alpha_, 1.0f / ior_);
        if (std::min(1.0f - e_avg_[0], 1.0f - e_avg_[1]) > 1e-5f) {
          ms_ = true;
          e_nodes_ = ggx_albedo_nodes(true);
          for (int i = 0; i < e_nodes_; ++i)
            for (int side = 0; side < 2; ++side)
              e_row_[side][i] = ggx_dielectric_albedo(float(i) / float(e_nodes_ - 1), alpha_, side == 0 ? ior_ : 1.0f / ior_);
          int rare = ior_ >= 1 ? 0 : 1, dense = 1 - rare;
          float n2[2] = {1.0f, ior_ * ior_};
          reflect_[rare] = float(fresnel_dielectric_average(rare == 0 ? ior_ : 1.0 / ior_));
          float tau = (1.0f - reflect_[rare]) * (1.0f - e_avg_[rare]) * n2[rare];
          reflect_[dense] = std::clamp(1.0f - tau / ((1.0f - e_avg_[dense]) * n2[dense]), 0.0f, 1.0f);
        }
      }
      break;
  }
}

Material regularized(const Material& m) {
  // The roughness of the regularised alpha, or the roughness itself when alpha is rough enough.
  auto roughen = [](float roughness) {
    const float alpha = roughness * roughness;
    if (alpha >= kRegularizeAlphaMax) return roughness;
    return std::sqrt(std::clamp(2.0f * alpha, kRegularizeAlphaMin, kRegularizeAlphaMax));
  };
  Material r = m;
  switch (m.type) {
    case MaterialType::Glossy:
      if (m.lobe == GlossLobe::Phong) {
        // Walter et al. 2007's equivalence alpha = sqrt(2 / (n + 2)).
        const float alpha = std::sqrt(2.0f / (std::max(0.0f, m.exponent) + 2.0f));
        if (alpha < kRegularizeAlphaMax) {
          const float a = std::clamp(2.0f * alpha, kRegularizeAlphaMin, kRegularizeAlphaMax);
          r.exponent = 2.0f / (a * a) - 2.0f;
        }
      } else {
        r.roughness = roughen(m.roughness);
      }
      break;
    case MaterialType::Conductor:
    case MaterialType::Dielectric:
    case MaterialType::CoatedDiffuse:
      r.roughness = roughen(m.roughness);
      break;
    case MaterialType::Mirror:
      r.type = MaterialType::Glossy;
      r.lobe = GlossLobe::GGX;
      r.roughness = roughen(0.0f);
      break;
    default:
      break;
  }
  return r;
}

bool Bsdf::is_delta() const {
  return kind_ == Kind::Mirror || kind_ == Kind::SmoothConductor || kind_ == Kind::SmoothDielectric ||
         kind_ == Kind::ThinDielectric;
}
bool Bsdf::scatters() const { return kind_ != Kind::Black; }
Vec3 Bsdf::albedo() const { return albedo_; }

Vec3 Bsdf::eval(const Vec3& wo, const Vec3& wi) const {
  switch (kind_) {
    case Kind::Lambert:
      return same_hemisphere_up(wo, wi) ? albedo_ * kInvPi : Vec3(0.0f);
    case Kind::Ggx:
      return ms_ ? eval_ggx(wo, wi) + eval_ms(wo, wi) : eval_ggx(wo, wi);
    case Kind::Phong: {
      if (!same_hemisphere_up(wo, wi)) return Vec3(0.0f);
      float c = dot(wi, mirror_z(wo));
      if (c <= 0) return Vec3(0.0f);
      // Lafortune & Willems 1994 modified Phong, normalised so normal incidence reflects albedo.
      return albedo_ * ((exponent_ + 2.0f) * (0.5f * kInvPi) * std::pow(c, exponent_));
    }
    case Kind::RoughDielectric:
      return ms_ ? eval_rough_dielectric(wo, wi) + eval_ms(wo, wi) : eval_rough_dielectric(wo, wi);
    case Kind::Coated:
      return coated_.eval(wo, wi);
    default:
      return Vec3(0.0f);
  }
}

float Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  switch (kind_) {
    case Kind::Lambert:
      return same_hemisphere_up(wo, wi) ? wi.z * kInvPi : 0.0f;
    case Kind::Ggx:
    case Kind::RoughDielectric: {
      float ss = kind_ == Kind::Ggx ? pdf_ggx(wo, wi) : pdf_rough_dielectric(wo, wi);
      if (!ms_) return ss;
      float p = ms_probability(wo);
      return (1.0f - p) * ss + p * pdf_ms(wo, wi);
    }
    case Kind::Phong: {
      if (!same_hemisphere_up(wo, wi)) return 0.0f;
      float c = dot(wi, mirror_z(wo));
      if (c <= 0) return 0.0f;
      return (exponent_ + 1.0f) * (0.5f * kInvPi) * std::pow(c, exponent_);
    }
    case Kind::Coated:
      return coated_.pdf(wo, wi);
    default:
      return 0.0f;
  }
}

bool Bsdf::sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const {
  *out = BsdfSample{};
  switch (kind_) {
    case Kind::Lambert: {
      if (wo.z <= 0) return false;
      // Malley's method: uniform on the disk, projected up to the hemisphere.
      float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
      float z = std::sqrt(std::max(0.0f, 1.0f - u1));
      if (z <= 0) return false;
      out->wi = {r * std::cos(phi), r * std::sin(phi), z};
      out->pdf = z * kInvPi;
      out->weight = albedo_;
      return true;
    }
    case Kind::Ggx:
      return ms_ ? sample_compensated(wo, u1, u2, uc, out) : sample_ggx(wo, u1, u2, out);
    case Kind::Phong: {
      if (wo.z <= 0) return false;
      // cos(alpha) distributed as (n+1) c^n dc by inversion; 1 - u1 keeps c > 0.
      float c = std::pow(1.0f - u1, 1.0f / (exponent_ + 1.0f));
      float s = std::sqrt(std::max(0.0f, 1.0f - c * c)), phi = 2.0f * kPi * u2;
      Vec3 wi = Frame(mirror_z(wo)).to_world({s * std::cos(phi), s * std::sin(phi), c});
      if (wi.z <= 0) return false;  // below the horizon: the lobe is clipped there
      out->wi = normalize(wi);
      out->pdf = (exponent_ + 1.0f) * (0.5f * kInvPi) * std::pow(c, exponent_);
      out->weight = albedo_ * ((exponent_ + 2.0f) / (exponent_ + 1.0f) * wi.z);
      return true;
    }
    case Kind::Mirror:
      if (wo.z <= 0) return false;
      out->wi = mirror_z(wo);
      out->pdf = 1.0f;
      out->delta = true;
      out->weight = fresnel_schlick(albedo_, wo.z);
      return true;
    case Kind::SmoothConductor:
      if (wo.z <= 0) return false;
      out->wi = mirror_z(wo);
      out->pdf = 1.0f;
      out->delta = true;
      out->weight = fresnel_conductor(wo.z, eta_, k_);
      return true;
    case Kind::SmoothDielectric:
      return sample_smooth_dielectric(wo, uc, out);
    case Kind::ThinDielectric:
      return sample_thin_dielectric(wo, uc, out);
    case Kind::RoughDielectric:
      return ms_ ? sample_compensated(wo, u1, u2, uc, out) : sample_rough_dielectric(wo, u1, u2, uc, out);
    case Kind::Coated:
      return coated_.sample(wo, u1, u2, uc, out);
    default:
      return false;
  }
}

Vec3 Bsdf::fresnel_ggx(float cos_i) const {
  return conductor_ ? fresnel_conductor(cos_i, eta_, k_) : fresnel_schlick(albedo_, cos_i);
}

Vec3 Bsdf::eval_ggx(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere_up(wo, wi)) return Vec3(0.0f);
  Vec3 h = wo + wi;
  if (dot(h, h) == 0) return Vec3(0.0f);
  h = normalize(h);
  MicrofacetGgx ggx(alpha_);
  // Cook-Torrance / Walter 2007 eq. 20.
  return fresnel_ggx(dot(wi, h)) * (ggx.d(h) * ggx.g2(wo, wi) / (4.0f * wo.z * wi.z));
}

float Bsdf::pdf_ggx(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere_up(wo, wi)) return 0.0f;
  Vec3 h = wo + wi;
  if (dot(h, h) == 0) return 0.0f;
  h = normalize(h);
  // Visible-normal density times the reflection Jacobian dm/dwi = 1 / (4 wo.m).
  return MicrofacetGgx(alpha_).pdf_visible(wo, h) / (4.0f * dot(wo, h));
}

bool Bsdf::sample_ggx(const Vec3& wo, float u1, float u2, BsdfSample* out) const {
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
  out->weight = fresnel_ggx(c) * (ggx.g2(wo, wi) / ggx.g1(wo));
  return true;
}

// ---- Multiple-scattering compensation.

float Bsdf::ms_albedo(float mu, int side) const {
  // The tables are linear in mu between their nodes, so this equals the full lookup.
  float g = std::clamp(mu, 0.0f, 1.0f) * float(e_nodes_ - 1);
  int i = std::min(int(g), e_nodes_ - 2);
  const float* e = e_row_[side];
  return std::min(1.0f, e[i] + (e[i + 1] - e[i]) * (g - float(i)));
}

float Bsdf::ms_probability(const Vec3& wo) const {
  if (wo.z == 0 || (kind_ == Kind::Ggx && wo.z < 0)) return 0.0f;
  float e = ms_albedo(std::abs(wo.z), wo.z > 0 ? 0 : 1);
  // The dielectric's two lobes carry E and 1 - E of a white furnace; the conductor's E F_avg
  // and (1 - E) F_ms (channel means).
  if (kind_ == Kind::RoughDielectric) return 1.0f - e;
  float ss = e * ms_pick_ss_, ms = (1.0f - e) * ms_pick_ms_;
  return ss + ms > 0 ? ms / (ss + ms) : 0.0f;
}

Vec3 Bsdf::eval_ms(const Vec3& wo, const Vec3& wi) const {
  if (wo.z == 0 || wi.z == 0) return Vec3(0.0f);
  int so = wo.z > 0 ? 0 : 1, si = wi.z > 0 ? 0 : 1;
  float lo = 1.0f - ms_albedo(std::abs(wo.z), so);
  if (kind_ == Kind::Ggx) {
    if (so != 0 || si != 0) return Vec3(0.0f);
    return ms_scale_ * (lo * (1.0f - ms_albedo(wi.z, 0)));
  }
  float li = (1.0f - ms_albedo(std::abs(wi.z), si)) / (kPi * (1.0f - e_avg_[si]));
  if (so == si) return Vec3(reflect_[so] * lo * li);
  float eta = so == 0 ? ior_ : 1.0f / ior_;
  return albedo_ * ((1.0f - reflect_[so]) * lo * li / (eta * eta));
}

float Bsdf::pdf_ms(const Vec3& wo, const Vec3& wi) const {
  if (wo.z == 0 || wi.z == 0) return 0.0f;
  bool same = (wo.z > 0) == (wi.z > 0);
  if (kind_ == Kind::Ggx) return wo.z > 0 && same ? wi.z * kInvPi : 0.0f;
  float r = reflect_[wo.z > 0 ? 0 : 1];
  return (same ? r : 1.0f - r) * std::abs(wi.z) * kInvPi;
}

bool Bsdf::sample_compensated(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const {
  if (wo.z == 0 || (kind_ == Kind::Ggx && wo.z < 0)) return false;
  const float one_minus = 0x1.fffffep-1f;
  float p = ms_probability(wo);
  if (uc < p) {
    // The compensation lobe: reflect or transmit, then a cosine direction on that side (Malley).
    float v = std::min(uc / p, one_minus);
    bool transmit = kind_ == Kind::RoughDielectric && v >= reflect_[wo.z > 0 ? 0 : 1];
    float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
    float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    if (z <= 0) return false;
    float side = (wo.z > 0) != transmit ? 1.0f : -1.0f;
    out->wi = {r * std::cos(phi), r * std::sin(phi), side * z};
    out->transmission = transmit;
    out->eta = transmit ? (wo.z > 0 ? ior_ : 1.0f / ior_) : 1.0f;
  } else {
    float v = std::min((uc - p) / (1.0f - p), one_minus);
    bool ok = kind_ == Kind::Ggx ? sample_ggx(wo, u1, u2, out) : sample_rough_dielectric(wo, u1, u2, v, out);
    if (!ok) return false;
    // The single-scattering sampler gave f_ss cos / pdf_ss and pdf_ss: add the lobe to both.
    float cos_i = std::abs(out->wi.z), pdf_ss = out->pdf;
    out->pdf = (1.0f - p) * pdf_ss + p * pdf_ms(wo, out->wi);
    if (!(out->pdf > 0)) return false;
    out->weight = (out->weight * pdf_ss + eval_ms(wo, out->wi) * cos_i) / out->pdf;
    return true;
  }
  // A mixture: the weight is the whole f cos over the whole pdf, so that MIS sees the same pdf.
  out->pdf = pdf(wo, out->wi);
  if (!(out->pdf > 0)) return false;
  out->weight = eval(wo, out->wi) * (std::abs(out->wi.z) / out->pdf);
  return true;
}

double thin_dielectric_reflectance(double cos_i, double ior) {
  const double r = fresnel_dielectric(cos_i, ior), t = 1 - r;
  // The geometric series of inner bounces: each round trip reflects twice (R^2) and the light
  // leaves through the first face (T); r = 1 (grazing) stays 1.
  return r < 1 ? r + t * t * r / (1 - r * r) : 1.0;
}

bool Bsdf::sample_thin_dielectric(Vec3 wo, float uc, BsdfSample* out) const {
  if (wo.z == 0) return false;
  const double r = thin_dielectric_reflectance(std::abs(wo.z), ior_);
  out->delta = true;
  if (uc < r) {
    out->wi = mirror_z(wo);
    out->pdf = float(r);
    out->weight = Vec3(1.0f);  // R' with probability R'
    return true;
  }
  // Straight through: both faces refract by inverse amounts, so the direction and the
  // radiance (no 1/eta^2) are unchanged.
  out->wi = -wo;
  out->pdf = float(1 - r);
  out->transmission = true;
  out->weight = albedo_;
  return true;
}

bool Bsdf::sample_smooth_dielectric(Vec3 wo, float uc, BsdfSample* out) const {
  if (wo.z == 0) return false;
  float eta = wo.z > 0 ? ior_ : 1.0f / ior_;  // transmitted over incident
  Vec3 n{0, 0, wo.z > 0 ? 1.0f : -1.0f};
  double f = fresnel_dielectric(std::abs(wo.z), eta);
  out->delta = true;
  if (uc < f) {
    // f R cos / (cos F) with probability F: the weight is 1.
    out->wi = mirror_z(wo);
    out->pdf = float(f);
    out->weight = Vec3(1.0f);
    return true;
  }
  Vec3 wt;
  if (!refract(wo, n, eta, &wt)) return false;
  out->wi = normalize(wt);
  out->pdf = float(1.0 - f);
  out->transmission = true;
  out->eta = eta;
  // (1 - F) / eta^2 per unit projected solid angle, divided by the choice probability 1 - F.
  out->weight = albedo_ / (eta * eta);
  return true;
}

// Rough dielectric after Walter et al. 2007. Evaluated with wo flipped to the upper side: the
// microfacet distribution is symmetric about the macro surface, so looking from inside is
// looking from outside at an interface of relative index 1 / ior.

Vec3 Bsdf::eval_rough_dielectric(Vec3 wo, Vec3 wi) const {
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

float Bsdf::pdf_rough_dielectric(Vec3 wo, Vec3 wi) const {
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

bool Bsdf::sample_rough_dielectric(Vec3 wo, float u1, float u2, float uc, BsdfSample* out) const {
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

}  // namespace pdrt
