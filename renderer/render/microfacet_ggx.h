#pragma once
// Isotropic GGX / Trowbridge-Reitz microfacet distribution (Walter et al. 2007) with the
// height-correlated Smith masking-shadowing (Heitz 2014) and visible-normal sampling
// (Heitz 2018). Directions are in the local shading frame, macro normal = +z.
#include "renderer/scene/vec3.h"

namespace pdrt {

class MicrofacetGgx {
 public:
  explicit MicrofacetGgx(float alpha) : alpha_(alpha) {}
  float alpha() const { return alpha_; }

  // Normal distribution D(m) per unit solid angle of m; 0 for m below the macro surface.
  float d(const Vec3& m) const;
  // Smith's auxiliary function Lambda(w); depends on w only through |w.z|.
  float lambda(const Vec3& w) const;
  // Masking of one direction: G1 = 1 / (1 + Lambda).
  float g1(const Vec3& w) const { return 1.0f / (1.0f + lambda(w)); }
  // Height-correlated masking-shadowing, Heitz 2014 eq. 99: 1 / (1 + Lambda(wo) + Lambda(wi)).
  float g2(const Vec3& wo, const Vec3& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

  // Distribution of normals visible from w (Heitz 2014 eq. 16): G1(w) max(0, w.m) D(m) / |w.z|.
  // w is taken on the upper side (its z sign is ignored), so m.z > 0 always.
  float pdf_visible(const Vec3& w, const Vec3& m) const;
  // A normal m drawn with density pdf_visible(w, .) from u1, u2 in [0, 1) (Heitz 2018).
  Vec3 sample_visible(const Vec3& w, float u1, float u2) const;

 private:
  float alpha_;
};

}  // namespace pdrt
