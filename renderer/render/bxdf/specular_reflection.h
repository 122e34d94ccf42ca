#pragma once
// Delta reflections: the mirror (Schlick Fresnel with F0 = albedo) and the smooth conductor
// (exact conductor Fresnel with complex index eta + ik per RGB channel, fresnel_conductor).
#include "renderer/render/bxdf/bsdf_sample.h"

namespace pdrt {

struct SchlickMirrorBxdf {
  static constexpr bool kDelta = true;
  Vec3 albedo{0.0f};  // F0

  Vec3 eval(const Vec3&, const Vec3&) const { return Vec3(0.0f); }
  float pdf(const Vec3&, const Vec3&) const { return 0.0f; }
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;
  static constexpr bool uses_lobe_choice() { return false; }  // one direction, the mirror's
  static constexpr bool uses_direction() { return false; }
};

struct SmoothConductorBxdf {
  static constexpr bool kDelta = true;
  Vec3 eta{1.0f}, k{0.0f};

  Vec3 eval(const Vec3&, const Vec3&) const { return Vec3(0.0f); }
  float pdf(const Vec3&, const Vec3&) const { return 0.0f; }
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const;
  static constexpr bool uses_lobe_choice() { return false; }  // one direction, the mirror's
  static constexpr bool uses_direction() { return false; }
};

}  // namespace pdrt
