#include "renderer/render/lights/triangle_light.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

LightBounds TriangleLight::bounds() const {
  const EmbreeScene& s = *emitter.scene;
  const int shape = emitter.shape;
  LightBounds b;
  b.cos_e = 0;  // diffuse emission: pi/2 past the normal
  b.two_sided = emitter.material().two_sided;
  const auto& pos = s.positions(shape);
  const uint32_t* t = &s.indices(shape)[3 * std::size_t(prim)];
  const Vec3 a = pos[t[0]], bb = pos[t[1]], c = pos[t[2]];
  if (!s.moving(shape)) {
    b.box.extend(a), b.box.extend(bb), b.box.extend(c);
    const Vec3 n = cross(bb - a, c - a);
    const float len = length(n);
    b.phi = len > 0 ? emitter.luminance * 0.5f * len : 0.0f;  // L x area: zero-area triangles are never chosen
    b.normals = {len > 0 ? n / len : Vec3(0, 0, 1), 1.0f};
    return b;
  }
  float step = 0, area = 0;
  Vec3 prev[3];
  for (int k = 0; k < kTimeSamples; ++k) {
    const Affine xf = s.transform(shape, float(k) / (kTimeSamples - 1));
    const Vec3 w[3] = {xf.point(a), xf.point(bb), xf.point(c)};
    for (int j = 0; j < 3; ++j) {
      b.box.extend(w[j]);
      if (k > 0) step = std::max(step, length(w[j] - prev[j]));
      prev[j] = w[j];
    }
    area = std::max(area, 0.5f * length(cross(w[1] - w[0], w[2] - w[0])));
  }
  b.box.lo -= Vec3(step), b.box.hi += Vec3(step);
  b.phi = area > 0 ? emitter.luminance * area : 0.0f;
  b.normals = DirectionCone{};  // it may turn during the shutter
  return b;
}

void TriangleLight::corners(float time, Vec3* a, Vec3* b, Vec3* c) const {
  const EmbreeScene& s = *emitter.scene;
  const auto& pos = s.positions(emitter.shape);
  const uint32_t* t = &s.indices(emitter.shape)[3 * std::size_t(prim)];
  *a = pos[t[0]], *b = pos[t[1]], *c = pos[t[2]];
  if (s.moving(emitter.shape)) {
    Affine m = s.transform(emitter.shape, time);
    *a = m.point(*a), *b = m.point(*b), *c = m.point(*c);
  }
}

ErrorPoint TriangleLight::point_at(float time, float b1, float b2) const {
  const EmbreeScene& s = *emitter.scene;
  const auto& pos = s.positions(emitter.shape);
  const uint32_t* t = &s.indices(emitter.shape)[3 * std::size_t(prim)];
  ErrorPoint x = triangle_point(pos[t[0]], pos[t[1]], pos[t[2]], b1, b2);
  return s.moving(emitter.shape) ? transform_point(s.transform(emitter.shape, time), x) : x;
}

bool TriangleLight::sample(const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const {
  Vec3 a, b, c;
  corners(time, &a, &b, &c);
  // Uniform barycentrics (square-root map).
  float su = std::sqrt(float(u[0])), b0 = 1 - su, b1 = float(u[1]) * su;
  out->x = point_at(time, b1, 1 - b0 - b1);
  const Vec3 p = out->x.p;
  Vec3 n = cross(b - a, c - a);
  float area = 0.5f * length(n);
  if (area <= 0) return false;
  n = n / (2 * area);
  out->n = n;
  Vec3 d = p - ref;
  float d2 = dot(d, d);
  if (d2 <= 0) return false;
  float dist = std::sqrt(d2);
  out->wi = d / dist;
  out->dist = dist;
  float cos_l = -dot(n, out->wi);
  if (std::abs(cos_l) < 1e-7f) return false;
  const Material& m = emitter.material();
  SurfaceHit h;
  h.shape = emitter.shape, h.prim = prim, h.bary_u = b1, h.bary_v = 1 - b0 - b1;
  out->radiance = (cos_l > 0 || m.two_sided) ? emitter.radiance(m, h) : Vec3(0.0f);
  out->pdf = d2 / (std::abs(cos_l) * area);
  return true;
}

float TriangleLight::pdf(const Vec3& ref, const SurfaceHit& hit, float time, float pick) const {
  Vec3 a, b, c;
  corners(time, &a, &b, &c);
  float area = 0.5f * length(cross(b - a, c - a));
  Vec3 d = hit.p - ref;
  float d2 = dot(d, d);
  float cos_l = std::abs(dot(hit.ng, d)) / std::sqrt(d2);
  if (area <= 0 || cos_l <= 0) return 0;
  return pick * d2 / (cos_l * area);
}

}  // namespace pdrt
