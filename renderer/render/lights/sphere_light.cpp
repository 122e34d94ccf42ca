#include "renderer/render/lights/sphere_light.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace {

float sphere_radius_at(const EmbreeScene& s, int shape, const Affine& m) {
  return s.sphere_radius(shape) * (s.moving(shape) ? std::cbrt(std::abs(m.determinant())) : 1.0f);
}

// Whether a point at squared distance dc2 from the centre of a sphere of radius r samples it
// as from inside (by area) rather than by its cone. Points on the surface, up to float error
// (1e-4 in squared distance), count as inside: there the cone's half-angle nears 90 degrees
// and its pdf loses precision. sample() and pdf() must decide alike for MIS.
bool sees_sphere_from_inside(float dc2, float r) { return dc2 <= r * r * 1.0001f; }

// A world point p of sphere light `shape` as the hit texture_coords() reads: p_local is in the
// space its geometry is stored in (instance space for a moving sphere, world space else).
SurfaceHit sphere_hit(const EmbreeScene& s, int shape, const Affine& m, const Vec3& p) {
  SurfaceHit h;
  h.shape = shape;
  h.p = p;
  h.p_local = s.moving(shape) ? m.inverse().point(p) : p;
  return h;
}

// The point of a sphere light nearest to `near`, with the error of its (transformed) centre.
ErrorPoint sphere_light_point(const EmbreeScene& s, int shape, const Affine& m, const Vec3& c, float r,
                              const Vec3& near) {
  ErrorPoint x = sphere_point(c, r, near);
  if (s.moving(shape)) x.error += transform_point(m, {s.sphere_center(shape), Vec3(0.0f)}).error;
  return x;
}

// The sphere at the normalised time as seen from ref: transform, centre, radius and the
// vector to the centre with its squared length.
struct SphereView {
  Affine m;
  Vec3 c;
  float r;
  Vec3 to_c;
  float dc2;
};

SphereView view_from(const AreaEmitter& e, const Vec3& ref, float time) {
  SphereView v;
  v.m = e.scene->transform(e.shape, time);
  v.c = v.m.point(e.scene->sphere_center(e.shape));
  v.r = sphere_radius_at(*e.scene, e.shape, v.m);
  v.to_c = v.c - ref;
  v.dc2 = dot(v.to_c, v.to_c);
  return v;
}

// 1 - cos of the half-angle of the cone a sphere of radius r subtends at squared distance
// dc2, without cancellation for small spheres.
float one_minus_cos_max(float r, float dc2) {
  const float sin2_max = r * r / dc2, cos_max = std::sqrt(std::max(0.0f, 1 - sin2_max));
  return sin2_max / (1 + cos_max);
}

}  // namespace

LightBounds SphereLight::bounds() const {
  const EmbreeScene& s = *emitter.scene;
  const int shape = emitter.shape;
  const bool moving = s.moving(shape);
  LightBounds b;
  b.cos_e = 0;  // diffuse emission: pi/2 past the normal
  b.two_sided = emitter.material().two_sided;
  const Vec3 c0 = s.sphere_center(shape);
  float rmax = 0, step = 0;
  Vec3 prev;
  for (int k = 0; k < (moving ? kTimeSamples : 1); ++k) {
    const Affine xf = s.transform(shape, moving ? float(k) / (kTimeSamples - 1) : 0.0f);
    const Vec3 c = xf.point(c0);
    const float r = sphere_radius_at(s, shape, xf);
    b.box.extend(c - Vec3(r)), b.box.extend(c + Vec3(r));
    if (k > 0) step = std::max(step, length(c - prev));
    prev = c, rmax = std::max(rmax, r);
  }
  b.box.lo -= Vec3(step), b.box.hi += Vec3(step);
  b.phi = emitter.luminance * kPi * rmax * rmax;
  b.normals = DirectionCone{};
  return b;
}

bool SphereLight::sample_area(const Affine& m, const Vec3& c, float r, const Vec3& ref, std::array<double, 2> u,
                              LightSample* out) const {
  const EmbreeScene& s = *emitter.scene;
  float z = float(1 - 2 * u[0]), sn = std::sqrt(std::max(0.0f, 1 - z * z)), phi = float(2 * kPi * u[1]);
  Vec3 n(sn * std::cos(phi), sn * std::sin(phi), z);
  out->x = sphere_light_point(s, emitter.shape, m, c, r, c + n * r);
  out->n = n;
  Vec3 p = out->x.p, d = p - ref;
  float d2 = dot(d, d), dist = std::sqrt(d2);
  if (dist <= 0) return false;
  out->wi = d / dist, out->dist = dist;
  float cos_l = -dot(n, out->wi);
  if (std::abs(cos_l) < 1e-7f) return false;
  const Material& mat = emitter.material();
  out->radiance = (cos_l > 0 || mat.two_sided) ? emitter.radiance(mat, sphere_hit(s, emitter.shape, m, p)) : Vec3(0.0f);
  out->pdf = d2 / (std::abs(cos_l) * 4 * kPi * r * r);
  return true;
}

bool SphereLight::sample(const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const {
  const EmbreeScene& s = *emitter.scene;
  const SphereView v = view_from(emitter, ref, time);
  const Affine& m = v.m;
  const Vec3 c = v.c, to_c = v.to_c;
  const float r = v.r, dc2 = v.dc2;
  if (sees_sphere_from_inside(dc2, r)) return sample_area(m, c, r, ref, u, out);
  // Outside: uniform over the cone of directions the sphere subtends (pbrt-v3 §14.2.2).
  float dc = std::sqrt(dc2);
  float cone = one_minus_cos_max(r, dc2);
  float one_minus_cos = float(u[0]) * cone;
  float cos_t = 1 - one_minus_cos, sin_t = std::sqrt(std::max(0.0f, one_minus_cos * (2 - one_minus_cos)));
  float phi = float(2 * kPi * u[1]);
  Frame f(to_c / dc);
  Vec3 wi = f.to_world({sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t});
  // Distance to the near intersection of the sampled direction with the sphere.
  float b = dot(wi, to_c), disc = std::max(0.0f, r * r - (dc2 - b * b));
  float dist = b - std::sqrt(disc);
  out->wi = wi, out->dist = dist;
  out->x = sphere_light_point(s, emitter.shape, m, c, r, ref + wi * dist);
  out->n = normalize(out->x.p - c);
  out->radiance = emitter.radiance(emitter.material(), sphere_hit(s, emitter.shape, m, out->x.p));
  out->pdf = 1.0f / (2 * kPi * cone);
  return dist > 0;
}

float SphereLight::pdf(const Vec3& ref, const SurfaceHit& hit, float time, float pick) const {
  const SphereView v = view_from(emitter, ref, time);
  const float r = v.r;
  float density;
  if (sees_sphere_from_inside(v.dc2, r)) {
    Vec3 d = hit.p - ref;
    float d2 = dot(d, d), cos_l = std::abs(dot(hit.ng, d)) / std::sqrt(d2);
    density = cos_l > 0 ? d2 / (cos_l * 4 * kPi * r * r) : 0.0f;
  } else {
    density = 1.0f / (2 * kPi * one_minus_cos_max(r, v.dc2));
  }
  return pick * density;
}

}  // namespace pdrt
