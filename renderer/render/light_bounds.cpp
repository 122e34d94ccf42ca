#include "renderer/render/light_bounds.h"

#include <cmath>

namespace pdrt {

namespace {

float safe_sqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
float safe_acos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }

// Angle between unit vectors without acos's loss of precision near 0 and pi.
float angle_between(const Vec3& a, const Vec3& b) {
  if (dot(a, b) < 0) return kPi - 2 * std::asin(std::min(1.0f, length(a + b) * 0.5f));
  return 2 * std::asin(std::min(1.0f, length(b - a) * 0.5f));
}

// cos(max(0, a - b)) and sin(max(0, a - b)) from the sines and cosines of a and b.
float cos_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  return cos_a > cos_b ? 1.0f : cos_a * cos_b + sin_a * sin_b;
}
float sin_sub_clamped(float sin_a, float cos_a, float sin_b, float cos_b) {
  return cos_a > cos_b ? 0.0f : sin_a * cos_b - cos_a * sin_b;
}

}  // namespace

void Box3::extend(const Vec3& p) {
  lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
  hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
}

void Box3::extend(const Box3& b) {
  if (b.empty()) return;
  extend(b.lo), extend(b.hi);
}

float Box3::surface_area() const {
  if (empty()) return 0;
  Vec3 d = diagonal();
  return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

int Box3::max_axis() const {
  Vec3 d = diagonal();
  return d.x >= d.y && d.x >= d.z ? 0 : (d.y >= d.z ? 1 : 2);
}

DirectionCone DirectionCone::merge(const DirectionCone& a, const DirectionCone& b) {
  const float ta = safe_acos(a.cos_theta), tb = safe_acos(b.cos_theta), td = angle_between(a.w, b.w);
  if (std::min(td + tb, kPi) <= ta) return a;  // b lies inside a
  if (std::min(td + ta, kPi) <= tb) return b;
  // The cone spanning both: half-angle (ta + td + tb) / 2, axis a.w turned toward b.w.
  const float to = 0.5f * (ta + td + tb);
  if (to >= kPi) return {};
  Vec3 k = cross(a.w, b.w);
  float kl = length(k);
  if (kl == 0) return {};
  k = k / kl;
  const float tr = to - ta;  // Rodrigues' rotation of a.w about k (k is orthogonal to a.w)
  Vec3 w = a.w * std::cos(tr) + cross(k, a.w) * std::sin(tr);
  return {normalize(w), std::cos(to)};
}

LightBounds merge(const LightBounds& a, const LightBounds& b) {
  if (a.phi == 0) return b;
  if (b.phi == 0) return a;
  LightBounds m;
  m.box = a.box;
  m.box.extend(b.box);
  m.phi = a.phi + b.phi;
  m.normals = DirectionCone::merge(a.normals, b.normals);
  m.cos_e = std::min(a.cos_e, b.cos_e);
  m.two_sided = a.two_sided || b.two_sided;
  return m;
}

float LightBounds::importance(const Vec3& p, const Vec3& n) const { return PackedLightBounds(*this).importance(p, n); }

PackedLightBounds::PackedLightBounds(const LightBounds& b)
    : center(b.box.center()),
      w(b.normals.w),
      cos_o(b.normals.cos_theta),
      cos_e(b.cos_e),
      phi(b.phi),
      two_sided(b.two_sided) {
  r2 = 0.25f * dot(b.box.diagonal(), b.box.diagonal());  // bounding sphere of the box
  r = std::sqrt(r2);
  sin_o = safe_sqrt(1 - cos_o * cos_o);
}

float PackedLightBounds::importance(const Vec3& p, const Vec3& n) const {
  const Vec3 to_p = p - center;
  const float d2 = dot(to_p, to_p);
  // Inside the bounding sphere every direction is possible (theta_b = pi: every clamped
  // angle below is 0), and the distance is taken as the sphere's radius rather than letting
  // 1/d^2 blow up.
  if (d2 <= r2) return cos_e < 1 && r2 > 0 ? phi / r2 : 0.0f;
  const float inv_d = 1 / std::sqrt(d2);
  const Vec3 wi = to_p * inv_d;
  const float sin_b = std::min(1.0f, r * inv_d), cos_b = safe_sqrt(1 - sin_b * sin_b);
  // theta' = max(0, theta_w - theta_o - theta_b): the smallest angle between an emitter
  // normal and a direction from the box to p.
  float cos_p = 1;
  if (cos_o > -1) {
    float cos_w = dot(w, wi);
    if (two_sided) cos_w = std::abs(cos_w);
    const float sin_w = safe_sqrt(1 - cos_w * cos_w);
    const float cos_x = cos_sub_clamped(sin_w, cos_w, sin_o, cos_o);
    const float sin_x = sin_sub_clamped(sin_w, cos_w, sin_o, cos_o);
    cos_p = cos_sub_clamped(sin_x, cos_x, sin_b, cos_b);
  }
  if (cos_p <= cos_e) return 0;  // p is outside every emitter's emission cone: exact zero
  // The receiver's cosine, bounded the same way (|cos|: either side, for transmission).
  const float cos_i = std::abs(dot(wi, n)), sin_i = safe_sqrt(1 - cos_i * cos_i);
  return std::max(0.0f, phi * cos_p * cos_sub_clamped(sin_i, cos_i, sin_b, cos_b) / d2);
}

}  // namespace pdrt
