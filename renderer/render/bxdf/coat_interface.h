#pragma once
// The dielectric interface on top of a layered BSDF (layered.h): pbrt-v4's DielectricBxDF
// (bxdfs.h/.cpp), smooth (a delta pair: Fresnel reflection and Snell refraction) when the
// index is 1 or GGX alpha < 1e-3, else Walter et al. 2007's rough dielectric with
// height-correlated Smith G2 and visible-normal sampling; white, no energy compensation.
// eta is the index below over the index above. From below (wo.z < 0) both directions are
// mirrored through the surface and the index inverted: the microfacet distribution is
// symmetric under that mirror, so this is pbrt-v4's treatment of the inside.
#include "renderer/render/bxdf/layer_sample.h"
#include "renderer/render/microfacet_ggx.h"

namespace pdrt {

class CoatInterface {
 public:
  CoatInterface() = default;
  CoatInterface(float eta, float alpha)
      : eta_(eta), ggx_(alpha), specular_(eta == 1 || alpha < kEffectivelySmoothAlpha) {}

  bool specular() const { return specular_; }
  float f(Vec3 wo, Vec3 wi, Transport mode) const;  // 0 when specular
  float pdf(Vec3 wo, Vec3 wi, int lobes) const;     // 0 when specular
  bool sample(Vec3 wo, float uc, float u1, float u2, Transport mode, int lobes, LayerSample* out) const;

 private:
  float eta_ = 1.5f;
  MicrofacetGgx ggx_{1.0f};
  bool specular_ = true;
};

}  // namespace pdrt
