#pragma once
// What a BxDF's sample() returns, and the local-frame helpers every lobe shares. Directions
// are in the local shading frame (normal = +z); wo points away from the surface, toward the
// viewer; wi toward the light.
#include "renderer/scene/vec3.h"

namespace pdrt {

struct BsdfSample {
  Vec3 wi;             // local shading frame (normal = +z), unit length
  Vec3 weight;         // f(wo, wi) |cos wi| / pdf: the path-throughput factor
  float pdf = 0;       // solid-angle pdf of wi (for a delta lobe: the discrete probability of that lobe)
  bool delta = false;  // chosen lobe is a Dirac delta (mirror / smooth dielectric): not usable for MIS
  bool transmission = false;
  float eta = 1;  // transmitted over incident index for transmission, else 1 (radiance scales by 1/eta^2)
};

// Smallest GGX alpha: keeps rough lobes non-delta and their D finite in float.
inline constexpr float kMinGgxAlpha = 1e-3f;

inline bool same_hemisphere_up(const Vec3& wo, const Vec3& wi) { return wo.z > 0 && wi.z > 0; }
inline Vec3 mirror_z(const Vec3& w) { return {-w.x, -w.y, w.z}; }

}  // namespace pdrt
