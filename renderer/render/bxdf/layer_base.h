#pragma once
// The opaque bottom of a layered BSDF (layered.h): pbrt-v4's DiffuseBxDF (Lambert, reflectance
// r) or ConductorBxDF (exact conductor Fresnel of a complex index relative to the coat above;
// a delta mirror when GGX alpha < 1e-3, else the GGX microfacet BRDF with height-correlated
// G2 and visible-normal sampling, no energy compensation). Reflection only; from below
// (wo.z < 0) both directions are mirrored, as pbrt-v4's two-sided lobes.
#include "renderer/render/bxdf/layer_sample.h"
#include "renderer/render/microfacet_ggx.h"

namespace pdrt {

class LayerBase {
 public:
  static LayerBase diffuse(const Vec3& reflectance);
  static LayerBase conductor(const Vec3& eta, const Vec3& k, float alpha);

  bool specular() const { return conductor_ && alpha_ < kEffectivelySmoothAlpha; }
  Vec3 f(Vec3 wo, Vec3 wi) const;  // 0 when specular
  float pdf(Vec3 wo, Vec3 wi) const;
  bool sample(Vec3 wo, float u1, float u2, LayerSample* out) const;

 private:
  bool conductor_ = false;
  Vec3 r_{0.0f};  // diffuse reflectance
  Vec3 eta_{1.0f}, k_{0.0f};
  float alpha_ = 0;
};

}  // namespace pdrt
