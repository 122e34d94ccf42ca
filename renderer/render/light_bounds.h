#pragma once
// Spatial and directional bounds of one emitter or a group of them, and the importance of
// such a group at a shading point (pbrt-v4 §12.6.3 "Light Bounds"; Conty Estevez and Kulla,
// "Importance Sampling of Many Lights with Adaptive Tree Splitting", HPG 2018). The
// importance is a conservative estimate of the irradiance the group can deliver at p: it is
// zero only when no emitter of the group can send light toward p, which keeps sampling by it
// unbiased.
#include "renderer/scene/vec3.h"

#include <cmath>

namespace pdrt {

struct Box3 {
  Vec3 lo{1e30f}, hi{-1e30f};  // empty
  bool empty() const { return lo.x > hi.x; }
  void extend(const Vec3& p);
  void extend(const Box3& b);
  Vec3 center() const { return (lo + hi) * 0.5f; }
  Vec3 diagonal() const { return hi - lo; }
  float surface_area() const;
  int max_axis() const;
};

// A cone of unit directions: axis w and cosine of its half-angle (-1: the whole sphere).
struct DirectionCone {
  Vec3 w{0, 0, 1};
  float cos_theta = -1;
  // The smallest cone of this construction holding both (pbrt-v4 §3.8.4).
  static DirectionCone merge(const DirectionCone& a, const DirectionCone& b);
};

struct LightBounds {
  Box3 box;  // world box (for moving emitters: the union over the shutter)
  // Irradiance units: phi / d^2 estimates what the group delivers at distance d, so phi is
  // luminance x area for a flat emitter (L A cos / d^2 is the radiance times the solid angle
  // it subtends) and luminance x pi r^2 for a sphere (its projected area from any side).
  float phi = 0;
  DirectionCone normals;   // the emitters' front normals lie in this cone (cos theta_o)
  float cos_e = 0;         // emission reaches cos theta_e past the normal cone (diffuse: pi/2)
  bool two_sided = false;  // emits on both sides of each normal

  // Estimated irradiance at p on a surface of unit normal n (either side of it), from the
  // distance to the box, the angle between the normal cone and p, the angle the box
  // subtends from p (theta_b) and the receiver's cosine.
  float importance(const Vec3& p, const Vec3& n) const;
};

LightBounds merge(const LightBounds& a, const LightBounds& b);

// Moving emitters' boxes are the union of the boxes at kTimeSamples times over the shutter,
// padded by the largest step a point takes between two of them (a bound on how far it strays
// in between). Their normal cone is the whole sphere, so an error here changes only the
// estimate, never makes a contributing light's importance zero.
inline constexpr int kTimeSamples = 65;

// A light at infinity, beside the BVH, in the same units: its importance at a point of unit
// normal n is phi (the environment: pi x its mean luminance) or, for a directional one (a
// distant light arriving from w), phi |n . w|.
struct InfiniteLightBounds {
  Vec3 w{0.0f};
  float phi = 0;
  bool directional = false;
  float importance(const Vec3& n) const { return directional ? phi * std::abs(dot(n, w)) : phi; }
};

// What importance() reads, with its derived terms (box centre, bounding-sphere radius, sin
// theta_o) precomputed: the BVH evaluates it twice per level of every light choice.
struct PackedLightBounds {
  Vec3 center, w{0, 0, 1};
  float r2 = 0, r = 0, cos_o = 1, sin_o = 0, cos_e = 0, phi = 0;
  bool two_sided = false;
  PackedLightBounds() = default;
  explicit PackedLightBounds(const LightBounds& b);
  float importance(const Vec3& p, const Vec3& n) const;
};

}  // namespace pdrt
