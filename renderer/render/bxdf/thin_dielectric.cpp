#include "renderer/render/bxdf/thin_dielectric.h"

#include "renderer/render/fresnel.h"

#include <cmath>

namespace pdrt {

double thin_dielectric_reflectance(double cos_i, double ior) {
  const double r = fresnel_dielectric(cos_i, ior), t = 1 - r;
  // The geometric series of inner bounces: each round trip reflects twice (R^2) and the light
  // leaves through the first face (T); r = 1 (grazing) stays 1.
  return r < 1 ? r + t * t * r / (1 - r * r) : 1.0;
}

bool ThinDielectricBxdf::sample(const Vec3& wo, float, float, float uc, BsdfSample* out) const {
  if (wo.z == 0) return false;
  const double r = thin_dielectric_reflectance(std::abs(wo.z), ior);
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
  out->weight = albedo;
  return true;
}

}  // namespace pdrt
