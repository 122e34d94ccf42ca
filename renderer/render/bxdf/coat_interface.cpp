#include "renderer/render/bxdf/coat_interface.h"

#include "renderer/render/bxdf/bsdf_sample.h"
#include "renderer/render/fresnel.h"

#include <cmath>

namespace pdrt {
namespace {

// Mirrors wo (and wi) to the upper side; returns the index seen from wo's side.
float to_upper(float eta, Vec3* wo, Vec3* wi) {
  if (wo->z >= 0) return eta;
  wo->z = -wo->z;
  if (wi) wi->z = -wi->z;
  return 1.0f / eta;
}

// The generalised half vector of a refraction (Walter 2007 eq. 16), oriented up, with the
// cosines wo.m > 0 >= wi.m; false when none exists (the pair is not a refraction).
bool refraction_half(const Vec3& wo, const Vec3& wi, float eta, Vec3* m, float* om, float* im) {
  Vec3 h = wo + wi * eta;
  if (dot(h, h) == 0) return false;
  h = normalize(h);
  if (h.z < 0) h = -h;
  *m = h, *om = dot(wo, h), *im = dot(wi, h);
  return *om > 0 && *im < 0;
}

// Reflect and transmit probabilities of a sample restricted to `lobes`.
bool lobe_odds(float r, int lobes, float* pr, float* pt) {
  *pr = lobes & kLayerReflect ? r : 0.0f;
  *pt = lobes & kLayerTransmit ? 1.0f - r : 0.0f;
  return *pr + *pt > 0;
}

}  // namespace

float CoatInterface::f(Vec3 wo, Vec3 wi, Transport mode) const {
  if (specular_ || wo.z == 0 || wi.z == 0) return 0.0f;
  const float eta = to_upper(eta_, &wo, &wi);
  if (wi.z > 0) {
    Vec3 h = wo + wi;
    if (dot(h, h) == 0) return 0.0f;
    h = normalize(h);
    float fr = float(fresnel_dielectric(dot(wo, h), eta));
    return ggx_.d(h) * ggx_.g2(wo, wi) * fr / (4.0f * wo.z * wi.z);
  }
  Vec3 m;
  float om, im;
  if (!refraction_half(wo, wi, eta, &m, &om, &im)) return 0.0f;
  float t = 1.0f - float(fresnel_dielectric(om, eta));
  float denom = (im + om / eta) * (im + om / eta);
  float ft = ggx_.d(m) * t * ggx_.g2(wo, wi) * std::abs(im * om / (wi.z * wo.z * denom));
  return mode == Transport::Radiance ? ft / (eta * eta) : ft;
}

float CoatInterface::pdf(Vec3 wo, Vec3 wi, int lobes) const {
  if (specular_ || wo.z == 0 || wi.z == 0) return 0.0f;
  const float eta = to_upper(eta_, &wo, &wi);
  float pr, pt;
  if (wi.z > 0) {
    Vec3 h = wo + wi;
    if (dot(h, h) == 0) return 0.0f;
    h = normalize(h);
    float om = dot(wo, h);
    if (!lobe_odds(float(fresnel_dielectric(om, eta)), lobes, &pr, &pt)) return 0.0f;
    return ggx_.pdf_visible(wo, h) / (4.0f * om) * pr / (pr + pt);
  }
  Vec3 m;
  float om, im;
  if (!refraction_half(wo, wi, eta, &m, &om, &im)) return 0.0f;
  if (!lobe_odds(float(fresnel_dielectric(om, eta)), lobes, &pr, &pt)) return 0.0f;
  float denom = (im + om / eta) * (im + om / eta);
  return ggx_.pdf_visible(wo, m) * (-im / denom) * pt / (pr + pt);
}

bool CoatInterface::sample(Vec3 wo, float uc, float u1, float u2, Transport mode, int lobes, LayerSample* out) const {
  *out = LayerSample{};
  if (wo.z == 0) return false;
  const bool below = wo.z < 0;
  const float eta = to_upper(eta_, &wo, nullptr);
  float pr, pt;
  Vec3 wi;
  if (specular_) {
    const float r = float(fresnel_dielectric(wo.z, eta));
    if (!lobe_odds(r, lobes, &pr, &pt)) return false;
    out->specular = true;
    if (uc < pr / (pr + pt)) {
      wi = mirror_z(wo);
      out->f = Vec3(r / wi.z);
      out->pdf = pr / (pr + pt);
    } else {
      if (!refract(wo, Vec3{0, 0, 1}, eta, &wi)) return false;
      wi = normalize(wi);
      float ft = (1.0f - r) / std::abs(wi.z);
      out->f = Vec3(mode == Transport::Radiance ? ft / (eta * eta) : ft);
      out->pdf = pt / (pr + pt);
      out->transmission = true;
    }
  } else {
    const Vec3 m = ggx_.sample_visible(wo, u1, u2);
    const float om = dot(wo, m);
    if (om <= 0) return false;
    const float r = float(fresnel_dielectric(om, eta));
    if (!lobe_odds(r, lobes, &pr, &pt)) return false;
    if (uc < pr / (pr + pt)) {
      wi = normalize(reflect(wo, m));
      if (wi.z <= 0) return false;
      out->pdf = ggx_.pdf_visible(wo, m) / (4.0f * om) * pr / (pr + pt);
      out->f = Vec3(ggx_.d(m) * ggx_.g2(wo, wi) * r / (4.0f * wi.z * wo.z));
    } else {
      if (!refract(wo, m, eta, &wi)) return false;
      wi = normalize(wi);
      if (wi.z >= 0) return false;
      const float im = dot(wi, m), denom = (im + om / eta) * (im + om / eta);
      out->pdf = ggx_.pdf_visible(wo, m) * std::abs(im) / denom * pt / (pr + pt);
      float ft = (1.0f - r) * ggx_.d(m) * ggx_.g2(wo, wi) * std::abs(im * om / (wi.z * wo.z * denom));
      out->f = Vec3(mode == Transport::Radiance ? ft / (eta * eta) : ft);
      out->transmission = true;
    }
  }
  if (below) wi.z = -wi.z;
  out->wi = wi;
  return out->pdf > 0;
}

}  // namespace pdrt
