#pragma once
// TEMPORARY STUB (lead's local build only; replaced by the bsdf branch)
#include "material.h"
namespace pdrt {
struct BsdfSample { Vec3 wi; Vec3 weight; float pdf = 0; bool delta = false; bool transmission = false; };
class Bsdf {
 public:
  explicit Bsdf(const Material& m) : m_(m) {}
  Vec3 eval(const Vec3& wo, const Vec3& wi) const { return (wo.z > 0 && wi.z > 0 && m_.type == MaterialType::Diffuse) ? m_.albedo * kInvPi : Vec3(0.0f); }
  float pdf(const Vec3& wo, const Vec3& wi) const { return (wo.z > 0 && wi.z > 0) ? wi.z * kInvPi : 0.0f; }
  bool sample(const Vec3& wo, float u1, float u2, float, BsdfSample* out) const {
    if (wo.z <= 0 || m_.type == MaterialType::Emitter) return false;
    if (m_.type == MaterialType::Mirror) { out->wi = {-wo.x, -wo.y, wo.z}; out->weight = m_.albedo; out->pdf = 1; out->delta = true; return true; }
    float r = std::sqrt(u1), phi = 2 * kPi * u2;
    out->wi = {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1 - u1))};
    out->pdf = out->wi.z * kInvPi; out->weight = m_.albedo; out->delta = false; return out->pdf > 0;
  }
  bool is_delta() const { return m_.type == MaterialType::Mirror; }
  bool scatters() const { return m_.type != MaterialType::Emitter; }
  Vec3 albedo() const { return m_.albedo; }
 private:
  Material m_;
};
}
