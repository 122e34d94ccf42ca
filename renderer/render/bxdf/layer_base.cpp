#include "renderer/render/bxdf/layer_base.h"

#include "renderer/render/bxdf/bsdf_sample.h"
#include "renderer/render/fresnel.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

LayerBase LayerBase::diffuse(const Vec3& reflectance) {
  LayerBase b;
  b.r_ = reflectance;
  return b;
}

LayerBase LayerBase::conductor(const Vec3& eta, const Vec3& k, float alpha) {
  LayerBase b;
  b.conductor_ = true;
  b.eta_ = eta, b.k_ = k, b.alpha_ = alpha;
  return b;
}

Vec3 LayerBase::f(Vec3 wo, Vec3 wi) const {
  if (wo.z * wi.z <= 0) return Vec3(0.0f);
  if (!conductor_) return r_ * kInvPi;
  if (specular()) return Vec3(0.0f);
  if (wo.z < 0) wo.z = -wo.z, wi.z = -wi.z;
  Vec3 h = wo + wi;
  if (dot(h, h) == 0) return Vec3(0.0f);
  h = normalize(h);
  MicrofacetGgx ggx(alpha_);
  return fresnel_conductor(dot(wo, h), eta_, k_) * (ggx.d(h) * ggx.g2(wo, wi) / (4.0f * wo.z * wi.z));
}

float LayerBase::pdf(Vec3 wo, Vec3 wi) const {
  if (wo.z * wi.z <= 0) return 0.0f;
  if (!conductor_) return std::abs(wi.z) * kInvPi;
  if (specular()) return 0.0f;
  if (wo.z < 0) wo.z = -wo.z, wi.z = -wi.z;
  Vec3 h = wo + wi;
  if (dot(h, h) == 0) return 0.0f;
  h = normalize(h);
  return MicrofacetGgx(alpha_).pdf_visible(wo, h) / (4.0f * dot(wo, h));
}

bool LayerBase::sample(Vec3 wo, float u1, float u2, LayerSample* out) const {
  *out = LayerSample{};
  if (wo.z == 0) return false;
  const bool below = wo.z < 0;
  if (below) wo.z = -wo.z;
  Vec3 wi;
  if (!conductor_) {
    // Cosine-weighted (Malley's method).
    float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
    wi = {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u1))};
    if (wi.z <= 0) return false;
    out->f = r_ * kInvPi;
    out->pdf = wi.z * kInvPi;
  } else if (specular()) {
    wi = mirror_z(wo);
    out->f = fresnel_conductor(wi.z, eta_, k_) / wi.z;
    out->pdf = 1.0f;
    out->specular = true;
  } else {
    MicrofacetGgx ggx(alpha_);
    const Vec3 m = ggx.sample_visible(wo, u1, u2);
    const float om = dot(wo, m);
    if (om <= 0) return false;
    wi = normalize(reflect(wo, m));
    if (wi.z <= 0) return false;
    out->pdf = ggx.pdf_visible(wo, m) / (4.0f * om);
    out->f = fresnel_conductor(om, eta_, k_) * (ggx.d(m) * ggx.g2(wo, wi) / (4.0f * wo.z * wi.z));
  }
  if (below) wi.z = -wi.z;
  out->wi = wi;
  return out->pdf > 0;
}

}  // namespace pdrt
