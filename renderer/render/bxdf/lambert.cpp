#include "renderer/render/bxdf/lambert.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

Vec3 LambertBxdf::eval(const Vec3& wo, const Vec3& wi) const {
  return same_hemisphere_up(wo, wi) ? albedo * kInvPi : Vec3(0.0f);
}

float LambertBxdf::pdf(const Vec3& wo, const Vec3& wi) const {
  return same_hemisphere_up(wo, wi) ? wi.z * kInvPi : 0.0f;
}

bool LambertBxdf::sample(const Vec3& wo, float u1, float u2, float, BsdfSample* out) const {
  if (wo.z <= 0) return false;
  // Malley's method: uniform on the disk, projected up to the hemisphere.
  float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
  float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  if (z <= 0) return false;
  out->wi = {r * std::cos(phi), r * std::sin(phi), z};
  out->pdf = z * kInvPi;
  out->weight = albedo;
  return true;
}

}  // namespace pdrt
