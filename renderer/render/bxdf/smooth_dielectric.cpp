#include "renderer/render/bxdf/smooth_dielectric.h"

#include "renderer/render/fresnel.h"

#include <cmath>

namespace pdrt {

bool SmoothDielectricBxdf::sample(const Vec3& wo, float, float, float uc, BsdfSample* out) const {
  if (wo.z == 0) return false;
  float eta = wo.z > 0 ? ior : 1.0f / ior;  // transmitted over incident
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
  out->weight = albedo / (eta * eta);
  return true;
}

}  // namespace pdrt
