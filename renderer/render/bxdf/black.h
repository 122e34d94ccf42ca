#pragma once
// The BxDF of a surface that does not scatter (emitters): nothing is reflected or sampled.
#include "renderer/render/bxdf/bsdf_sample.h"

namespace pdrt {

struct BlackBxdf {
  static constexpr bool kDelta = false;
  Vec3 eval(const Vec3&, const Vec3&) const { return Vec3(0.0f); }
  float pdf(const Vec3&, const Vec3&) const { return 0.0f; }
  bool sample(const Vec3&, float, float, float, BsdfSample*) const { return false; }
  static constexpr bool uses_lobe_choice() { return false; }
  static constexpr bool uses_direction() { return false; }
};

}  // namespace pdrt
