#include "renderer/render/microfacet_ggx.h"

namespace pdrt {

float MicrofacetGgx::d(const Vec3& m) const {
  if (m.z <= 0) return 0;
  // Walter 2007 eq. 33 rewritten with cos^2: a^2 / (pi ((a^2 - 1) cos^2 + 1)^2), no tan needed.
  float a2 = alpha_ * alpha_;
  float c2 = m.z * m.z / dot(m, m);
  float t = (a2 - 1.0f) * c2 + 1.0f;
  return a2 / (kPi * t * t);
}

float MicrofacetGgx::lambda(const Vec3& w) const {
  float c2 = w.z * w.z;
  float s2 = std::max(0.0f, w.x * w.x + w.y * w.y);
  if (c2 == 0) return s2 > 0 ? INFINITY : 0.0f;
  // Heitz 2014 eq. 86: (-1 + sqrt(1 + a^2 tan^2)) / 2.
  float a2t2 = alpha_ * alpha_ * s2 / c2;
  return 0.5f * (std::sqrt(1.0f + a2t2) - 1.0f);
}

float MicrofacetGgx::pdf_visible(const Vec3& w, const Vec3& m) const {
  float cz = std::abs(w.z);
  if (cz == 0) return 0;
  Vec3 wu{w.x, w.y, cz};
  float wm = dot(wu, m);
  if (wm <= 0) return 0;
  return g1(wu) * wm * d(m) / cz;
}

Vec3 MicrofacetGgx::sample_visible(const Vec3& w, float u1, float u2) const {
  // Heitz 2018 §3: stretch the view direction to the alpha = 1 configuration, where the visible
  // normals are a hemisphere seen from vh, i.e. a projected disk; sample that disk, warping the
  // half that is partly hidden, lift to the hemisphere, and unstretch.
  Vec3 vh = normalize(Vec3{alpha_ * w.x, alpha_ * w.y, std::abs(w.z)});
  float len2 = vh.x * vh.x + vh.y * vh.y;
  Vec3 t1 = len2 > 0 ? Vec3{-vh.y, vh.x, 0} / std::sqrt(len2) : Vec3{1, 0, 0};
  Vec3 t2 = cross(vh, t1);
  float r = std::sqrt(u1);
  float phi = 2.0f * kPi * u2;
  float p1 = r * std::cos(phi);
  float p2 = r * std::sin(phi);
  float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
  Vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2));
  return normalize(Vec3{alpha_ * nh.x, alpha_ * nh.y, std::max(1e-7f, nh.z)});
}

}  // namespace pdrt
