#pragma once
// The Henyey-Greenstein phase function of the medium between a layered BSDF's interfaces
// (layered.h), in pbrt-v4's convention (media.h, HGPhaseFunction): wo and wi both point away
// from the scattering point, so forward scattering (g > 0) peaks at wi = -wo; g is clamped to
// [-0.99, 0.99] as pbrt-v4 does, where the inversion below stays finite.
#include "renderer/scene/vec3.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

class HenyeyGreenstein {
 public:
  explicit HenyeyGreenstein(float g) : g_(std::clamp(g, -0.99f, 0.99f)) {}

  // Density per unit solid angle of wi given wo (cos_theta = wo . wi).
  float p(float cos_theta) const {
    float denom = 1.0f + g_ * g_ + 2.0f * g_ * cos_theta;
    return (1.0f - g_ * g_) / (4.0f * kPi * denom * std::sqrt(std::max(denom, 0.0f)));
  }
  float p(const Vec3& wo, const Vec3& wi) const { return p(dot(wo, wi)); }

  // wi with density p(wo, .) (its value in *pdf), by inverting the cosine's distribution.
  Vec3 sample(const Vec3& wo, float u1, float u2, float* pdf) const {
    float c;
    if (std::abs(g_) < 1e-3f) {
      c = 1.0f - 2.0f * u1;
    } else {
      float s = (1.0f - g_ * g_) / (1.0f + g_ - 2.0f * g_ * u1);
      c = -(1.0f + g_ * g_ - s * s) / (2.0f * g_);
    }
    c = std::clamp(c, -1.0f, 1.0f);
    float sn = std::sqrt(std::max(0.0f, 1.0f - c * c)), phi = 2.0f * kPi * u2;
    Frame fr(wo);
    *pdf = p(c);
    return normalize(fr.to_world(Vec3{sn * std::cos(phi), sn * std::sin(phi), c}));
  }

 private:
  float g_;
};

}  // namespace pdrt
