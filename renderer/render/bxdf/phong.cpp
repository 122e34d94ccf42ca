#include "renderer/render/bxdf/phong.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

Vec3 PhongBxdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere_up(wo, wi)) return Vec3(0.0f);
  float c = dot(wi, mirror_z(wo));
  if (c <= 0) return Vec3(0.0f);
  // Normalised so that normal incidence reflects albedo.
  return albedo * ((exponent + 2.0f) * (0.5f * kInvPi) * std::pow(c, exponent));
}

float PhongBxdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere_up(wo, wi)) return 0.0f;
  float c = dot(wi, mirror_z(wo));
  if (c <= 0) return 0.0f;
  return (exponent + 1.0f) * (0.5f * kInvPi) * std::pow(c, exponent);
}

bool PhongBxdf::sample(const Vec3& wo, float u1, float u2, float, BsdfSample* out) const {
  if (wo.z <= 0) return false;
  // cos(alpha) distributed as (n+1) c^n dc by inversion; 1 - u1 keeps c > 0.
  float c = std::pow(1.0f - u1, 1.0f / (exponent + 1.0f));
  float s = std::sqrt(std::max(0.0f, 1.0f - c * c)), phi = 2.0f * kPi * u2;
  Vec3 wi = Frame(mirror_z(wo)).to_world({s * std::cos(phi), s * std::sin(phi), c});
  if (wi.z <= 0) return false;  // below the horizon: the lobe is clipped there
  out->wi = normalize(wi);
  out->pdf = (exponent + 1.0f) * (0.5f * kInvPi) * std::pow(c, exponent);
  out->weight = albedo * ((exponent + 2.0f) / (exponent + 1.0f) * wi.z);
  return true;
}

}  // namespace pdrt
