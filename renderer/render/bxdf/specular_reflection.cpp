#include "renderer/render/bxdf/specular_reflection.h"

#include "renderer/render/fresnel.h"

namespace pdrt {

bool SchlickMirrorBxdf::sample(const Vec3& wo, float, float, float, BsdfSample* out) const {
  if (wo.z <= 0) return false;
  out->wi = mirror_z(wo);
  out->pdf = 1.0f;
  out->delta = true;
  out->weight = fresnel_schlick(albedo, wo.z);
  return true;
}

bool SmoothConductorBxdf::sample(const Vec3& wo, float, float, float, BsdfSample* out) const {
  if (wo.z <= 0) return false;
  out->wi = mirror_z(wo);
  out->pdf = 1.0f;
  out->delta = true;
  out->weight = fresnel_conductor(wo.z, eta, k);
  return true;
}

}  // namespace pdrt
