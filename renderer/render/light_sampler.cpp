#include "renderer/render/light_sampler.h"

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
// and its pdf loses precision. sample_sphere and sphere_pdf must decide alike for MIS.
bool sees_sphere_from_inside(float dc2, float r) { return dc2 <= r * r * 1.0001f; }

// pbrt-v4's SmoothStep: 0 at x <= a, 1 at x >= b, a cubic between (a step when a == b).
float smoothstep(float x, float a, float b) {
  if (a == b) return x < a ? 0.0f : 1.0f;
  const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

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
ErrorPoint sphere_light_point(const EmbreeScene& s, int shape, const Affine& m, const Vec3& c, float r, const Vec3& near) {
  ErrorPoint x = sphere_point(c, r, near);
  if (s.moving(shape)) x.error += transform_point(m, {s.sphere_center(shape), Vec3(0.0f)}).error;
  return x;
}

}  // namespace

// Moving emitters: the box over the shutter of points that follow the shape's transform,
// from the transform at kTimeSamples times, padded by the largest step a point takes between
// two samples (a bound on how far it strays from the sampled positions in between). Their
// normal cone is the whole sphere, so an error here changes only the estimate, never makes
// a contributing light's importance zero.
constexpr int kTimeSamples = 65;

namespace {

int radiance_texture(const Material& m) {
  for (const TextureBinding& b : m.textures)
    if (b.param == MaterialParam::Radiance) return b.texture;
  return -1;
}

}  // namespace

Vec3 LightSampler::emitter_radiance(const Material& m, SurfaceHit h) const {
  const int t = radiance_texture(m);
  if (t < 0) return m.radiance;
  scene_.texture_coords(&h, 0);  // u, v do not depend on the time
  TextureCoords tc;
  tc.u = h.u, tc.v = h.v;  // a point lookup: a light sample is a point, not a pixel's footprint
  return emission(m.radiance, textures_.eval(t, tc));
}

float LightSampler::emitter_luminance(const Material& m) const {
  const int t = radiance_texture(m);
  if (t < 0) return luminance(m.radiance);
  double sum = 0;
  constexpr int n = 32;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      TextureCoords tc;
      tc.u = (i + 0.5f) / n, tc.v = (j + 0.5f) / n;
      sum += luminance(emission(m.radiance, textures_.eval(t, tc)));
    }
  return float(sum / (n * n));
}

LightSampler::LightSampler(const EmbreeScene& scene, const TextureSet& textures)
    : scene_(scene), textures_(textures) {
  const SceneDesc& d = scene.desc();
  first_entry_.assign(d.shapes.size(), -1);
  for (std::size_t i = 0; i < d.shapes.size(); ++i) {
    const ShapeDesc& s = d.shapes[i];
    const Material& m = d.materials[s.material];
    if (m.type != MaterialType::Emitter || is_black(m.radiance)) continue;
    first_entry_[i] = int64_t(entries_.size());
    if (s.kind == ShapeDesc::Kind::Sphere) {
      entries_.push_back({int(i), -1});
      continue;
    }
    for (std::size_t t = 0; t < scene.indices(int(i)).size() / 3; ++t) entries_.push_back({int(i), int(t)});
  }
  // Point and spot lights join the BVH after every shape's entries (so a shape's entries stay
  // contiguous); distant lights stay outside it, beside the environment.
  for (std::size_t k = 0; k < d.delta_lights.size(); ++k) {
    const DeltaLightDesc& l = d.delta_lights[k];
    if (l.kind != DeltaLightDesc::Kind::Distant) {
      if (!is_black(l.intensity)) entries_.push_back({-1, -1, int(k)});
    } else if (!is_black(l.irradiance)) {
      distant_.push_back({-l.direction, l.irradiance, std::max(luminance(l.irradiance), 1e-6f)});
    }
  }
  std::vector<LightBounds> bounds;
  bounds.reserve(entries_.size());
  for (const Entry& e : entries_) bounds.push_back(bounds_of(e));
  bvh_ = LightBvh(bounds);
  // The environment's estimated contribution in the BVH's units (irradiance): a constant
  // radiance L over the hemisphere on either side of n delivers E = pi L; an image, pi
  // times its mean luminance over the sphere. No scene-size term: the lights' importance
  // falls with distance, the environment's does not.
  if (d.environment.has_map()) {
    const EnvironmentDesc& e = d.environment;
    map_ = EnvironmentMap(e.width, e.height, e.rgb, e.scale, e.rotation_deg);
    env_irradiance_ = map_.irradiance_estimate();
  } else {
    env_ = d.environment.radiance;
    if (!is_black(env_)) env_irradiance_ = kPi * std::max(luminance(env_), 1e-6f);
  }
}

void LightSampler::delta_light_at(int delta, float time, Vec3* p, Vec3* axis) const {
  const DeltaLightDesc& l = scene_.desc().delta_lights[delta];
  Affine m = l.transform;
  if (!l.motion.empty()) {
    const CameraDesc& c = scene_.desc().camera;  // time is normalised to the shutter
    const float t = c.shutter_open + time * (c.shutter_close - c.shutter_open);
    m = interpolate(l.motion.data(), int(l.motion.size()), t).matrix() * l.transform;
  }
  *p = m.point(l.position);
  if (axis) *axis = normalize(m.vector(l.direction));
}

// A point light emits into every direction: a point box, the whole sphere of normals, phi =
// luminance of I, so that phi cos / d^2 is the irradiance I cos / d^2 it delivers (the BVH's
// units; pbrt-v4's phi is the power 4 pi I). A spot light adds its cone: normals within the
// falloff start, emission reaching the cone's edge (plus 1e-3 rad of slop for the rounding of
// the importance's angles, so a point just inside the cone never gets importance 0). A moving
// one has the box over the shutter and, since it may turn, the whole sphere of normals.
LightBounds LightSampler::delta_bounds(int delta) const {
  const DeltaLightDesc& l = scene_.desc().delta_lights[delta];
  const bool spot = l.kind == DeltaLightDesc::Kind::Spot;
  LightBounds b;
  b.phi = std::max(luminance(l.intensity), 1e-6f);
  b.cos_e = 0;
  b.normals = DirectionCone{};
  if (l.motion.empty()) {
    Vec3 p, axis;
    delta_light_at(delta, 0, &p, &axis);
    b.box.extend(p);
    if (spot && is_finite(axis)) {
      const float start = std::acos(std::clamp(l.cos_falloff_start, -1.0f, 1.0f));
      const float end = std::acos(std::clamp(l.cos_cone, -1.0f, 1.0f));
      b.normals = {axis, l.cos_falloff_start};
      b.cos_e = std::cos(std::min(kPi, end - start + 1e-3f));
    }
    return b;
  }
  float step = 0;
  Vec3 prev;
  for (int k = 0; k < kTimeSamples; ++k) {
    Vec3 p;
    delta_light_at(delta, float(k) / (kTimeSamples - 1), &p, nullptr);
    b.box.extend(p);
    if (k > 0) step = std::max(step, length(p - prev));
    prev = p;
  }
  b.box.lo -= Vec3(step), b.box.hi += Vec3(step);
  return b;
}

LightBounds LightSampler::bounds_of(const Entry& e) const {
  if (e.delta >= 0) return delta_bounds(e.delta);
  const Material& m = scene_.desc().materials[scene_.desc().shapes[e.shape].material];
  const float lum = std::max(emitter_luminance(m), 1e-6f);
  const bool moving = scene_.moving(e.shape);
  LightBounds b;
  b.cos_e = 0;  // diffuse emission: pi/2 past the normal
  b.two_sided = m.two_sided;
  if (e.prim < 0) {
    // A sphere emits in every direction: full normal cone; phi uses its projected area.
    const Vec3 c0 = scene_.sphere_center(e.shape);
    float rmax = 0, step = 0;
    Vec3 prev;
    for (int k = 0; k < (moving ? kTimeSamples : 1); ++k) {
      const Affine xf = scene_.transform(e.shape, moving ? float(k) / (kTimeSamples - 1) : 0.0f);
      const Vec3 c = xf.point(c0);
      const float r = sphere_radius_at(scene_, e.shape, xf);
      b.box.extend(c - Vec3(r)), b.box.extend(c + Vec3(r));
      if (k > 0) step = std::max(step, length(c - prev));
      prev = c, rmax = std::max(rmax, r);
    }
    b.box.lo -= Vec3(step), b.box.hi += Vec3(step);
    b.phi = lum * kPi * rmax * rmax;
    b.normals = DirectionCone{};
    return b;
  }
  const auto& pos = scene_.positions(e.shape);
  const uint32_t* t = &scene_.indices(e.shape)[3 * std::size_t(e.prim)];
  const Vec3 a = pos[t[0]], bb = pos[t[1]], c = pos[t[2]];
  if (!moving) {
    b.box.extend(a), b.box.extend(bb), b.box.extend(c);
    const Vec3 n = cross(bb - a, c - a);
    const float len = length(n);
    b.phi = len > 0 ? lum * 0.5f * len : 0.0f;  // L x area: zero-area triangles are never chosen
    b.normals = {len > 0 ? n / len : Vec3(0, 0, 1), 1.0f};
    return b;
  }
  float step = 0, area = 0;
  Vec3 prev[3];
  for (int k = 0; k < kTimeSamples; ++k) {
    const Affine xf = scene_.transform(e.shape, float(k) / (kTimeSamples - 1));
    const Vec3 w[3] = {xf.point(a), xf.point(bb), xf.point(c)};
    for (int j = 0; j < 3; ++j) {
      b.box.extend(w[j]);
      if (k > 0) step = std::max(step, length(w[j] - prev[j]));
      prev[j] = w[j];
    }
    area = std::max(area, 0.5f * length(cross(w[1] - w[0], w[2] - w[0])));
  }
  b.box.lo -= Vec3(step), b.box.hi += Vec3(step);
  b.phi = area > 0 ? lum * area : 0.0f;
  b.normals = DirectionCone{};  // it may turn during the shutter
  return b;
}

void LightSampler::triangle_at(int shape, int prim, float time, Vec3* a, Vec3* b, Vec3* c) const {
  const auto& pos = scene_.positions(shape);
  const uint32_t* t = &scene_.indices(shape)[3 * std::size_t(prim)];
  *a = pos[t[0]], *b = pos[t[1]], *c = pos[t[2]];
  if (scene_.moving(shape)) {
    Affine m = scene_.transform(shape, time);
    *a = m.point(*a), *b = m.point(*b), *c = m.point(*c);
  }
}

ErrorPoint LightSampler::triangle_point_at(int shape, int prim, float time, float b1, float b2) const {
  const auto& pos = scene_.positions(shape);
  const uint32_t* t = &scene_.indices(shape)[3 * std::size_t(prim)];
  ErrorPoint x = triangle_point(pos[t[0]], pos[t[1]], pos[t[2]], b1, b2);
  return scene_.moving(shape) ? transform_point(scene_.transform(shape, time), x) : x;
}

bool LightSampler::select(const Vec3& ref, const Vec3& n, float u, std::size_t* light, float* pmf) const {
  // The lights outside the BVH (distant lights, then the environment) against the BVH's root,
  // all as irradiance estimates: each takes its share of [0, 1) in turn, the BVH the rest,
  // with the pick number rescaled to it. Without lights outside it the root's importance is
  // not needed (the BVH fails if all of its lights have none). select_pmf() repeats exactly
  // this arithmetic.
  const std::size_t ni = infinite_count();
  float inf = 0;
  for (std::size_t k = 0; k < ni; ++k) inf += infinite_importance(k, n);
  const float b = inf > 0 ? bvh_.importance(ref, n) : 1.0f, total = inf + b;
  if (!(total > 0)) return false;
  float c = 0;  // the shares of the lights outside the BVH passed so far
  for (std::size_t k = 0; k < ni; ++k) {
    const float p = infinite_importance(k, n) / total;
    if (p > 0 && u < c + p) {
      *light = entries_.size() + k, *pmf = p;
      return true;
    }
    c += p;
  }
  if (!(b > 0 && c < 1)) return false;
  u = std::min((u - c) / (1 - c), 0x1.fffffep-1f);
  int id;
  float pb;
  if (!bvh_.sample(ref, n, u, &id, &pb)) return false;
  *light = std::size_t(id), *pmf = (1 - c) * pb;
  return *pmf > 0;
}

float LightSampler::select_pmf(const Vec3& ref, const Vec3& n, std::size_t light) const {
  const std::size_t ni = infinite_count();  // as in select()
  float inf = 0;
  for (std::size_t k = 0; k < ni; ++k) inf += infinite_importance(k, n);
  const float b = inf > 0 ? bvh_.importance(ref, n) : 1.0f, total = inf + b;
  if (!(total > 0)) return 0;
  if (light >= entries_.size()) {
    const std::size_t k = light - entries_.size();
    return k < ni ? infinite_importance(k, n) / total : 0.0f;
  }
  float c = 0;
  for (std::size_t k = 0; k < ni; ++k) c += infinite_importance(k, n) / total;
  if (!(b > 0 && c < 1)) return 0;
  return (1 - c) * bvh_.pmf(ref, n, int(light));
}

bool LightSampler::sample(const Vec3& ref, const Vec3& n, float time, float u_pick, std::array<double, 2> u,
                          LightSample* out) const {
  std::size_t e;
  float pick;
  if (!select(ref, n, u_pick, &e, &pick)) return false;
  bool ok;
  if (e == environment_id() && !map_.empty()) {
    out->dist = 1e30f;
    out->at_infinity = true;
    ok = map_.sample(u, &out->wi, &out->radiance, &out->pdf);
  } else if (e == environment_id()) {
    // Uniform over the sphere of directions.
    float z = float(1 - 2 * u[0]), r = std::sqrt(std::max(0.0f, 1 - z * z)), phi = float(2 * kPi * u[1]);
    out->wi = {r * std::cos(phi), r * std::sin(phi), z};
    out->dist = 1e30f;
    out->at_infinity = true;
    out->radiance = env_;
    out->pdf = 1.0f / (4 * kPi);
    ok = true;
  } else if (e >= entries_.size()) {
    // A distant light: one direction, its irradiance, probability 1 (times the pick).
    const Distant& l = distant_[e - entries_.size()];
    out->wi = l.to_light;
    out->dist = 1e30f;
    out->at_infinity = true;
    out->delta = true;
    out->radiance = l.irradiance;
    out->pdf = 1;
    ok = true;
  } else if (entries_[e].delta >= 0) {
    ok = sample_delta(entries_[e], ref, time, out);
  } else if (entries_[e].prim < 0) {
    ok = sample_sphere(entries_[e], ref, time, u, out);
  } else {
    ok = sample_triangle(entries_[e], ref, time, u, out);
  }
  if (!ok) return false;
  out->pdf *= pick;
  return out->pdf > 0;
}

// A point or spot light: the one direction to it, I falloff / d^2 (the irradiance at a
// surface facing it, as `radiance` so the integrator's f L |cos| / pdf holds), probability 1.
// The light-family pair u is not used: its values are a pure function of (pixel, sample,
// family, bounce), so leaving it unread shifts no other stream.
bool LightSampler::sample_delta(const Entry& e, const Vec3& ref, float time, LightSample* out) const {
  const DeltaLightDesc& l = scene_.desc().delta_lights[e.delta];
  const bool spot = l.kind == DeltaLightDesc::Kind::Spot;
  Vec3 p, axis;
  delta_light_at(e.delta, time, &p, spot ? &axis : nullptr);
  const Vec3 d = p - ref;
  const float d2 = dot(d, d);
  if (!(d2 > 0 && std::isfinite(d2)) || (spot && !is_finite(axis))) return false;
  const float dist = std::sqrt(d2);
  out->wi = d / dist, out->dist = dist;
  out->x = {p, Vec3(0.0f)};  // no geometry there: the shadow ray ends 1e-4 of its length short of p
  out->n = -out->wi;
  out->delta = true;
  const float falloff = spot ? smoothstep(-dot(axis, out->wi), l.cos_cone, l.cos_falloff_start) : 1.0f;
  out->radiance = l.intensity * (falloff / d2);
  out->pdf = 1;
  return true;
}

bool LightSampler::sample_triangle(const Entry& e, const Vec3& ref, float time, std::array<double, 2> u,
                                   LightSample* out) const {
  Vec3 a, b, c;
  triangle_at(e.shape, e.prim, time, &a, &b, &c);
  // Uniform barycentrics (square-root map).
  float su = std::sqrt(float(u[0])), b0 = 1 - su, b1 = float(u[1]) * su;
  out->x = triangle_point_at(e.shape, e.prim, time, b1, 1 - b0 - b1);
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
  const Material& m = scene_.desc().materials[scene_.desc().shapes[e.shape].material];
  if (std::abs(cos_l) < 1e-7f) return false;
  SurfaceHit h;
  h.shape = e.shape, h.prim = e.prim, h.bary_u = b1, h.bary_v = 1 - b0 - b1;
  out->radiance = (cos_l > 0 || m.two_sided) ? emitter_radiance(m, h) : Vec3(0.0f);
  out->pdf = d2 / (std::abs(cos_l) * area);
  return true;
}

bool LightSampler::sample_sphere(const Entry& e, const Vec3& ref, float time, std::array<double, 2> u,
                                 LightSample* out) const {
  Affine m = scene_.transform(e.shape, time);
  Vec3 c = m.point(scene_.sphere_center(e.shape));
  float r = sphere_radius_at(scene_, e.shape, m);
  const Material& mat = scene_.desc().materials[scene_.desc().shapes[e.shape].material];
  Vec3 to_c = c - ref;
  float dc2 = dot(to_c, to_c);
  if (sees_sphere_from_inside(dc2, r)) {
    // Inside (or on) the sphere: uniform area sampling.
    float z = float(1 - 2 * u[0]), s = std::sqrt(std::max(0.0f, 1 - z * z)), phi = float(2 * kPi * u[1]);
    Vec3 n(s * std::cos(phi), s * std::sin(phi), z);
    out->x = sphere_light_point(scene_, e.shape, m, c, r, c + n * r);
    out->n = n;
    Vec3 p = out->x.p, d = p - ref;
    float d2 = dot(d, d), dist = std::sqrt(d2);
    if (dist <= 0) return false;
    out->wi = d / dist, out->dist = dist;
    float cos_l = -dot(n, out->wi);
    if (std::abs(cos_l) < 1e-7f) return false;
    out->radiance = (cos_l > 0 || mat.two_sided) ? emitter_radiance(mat, sphere_hit(scene_, e.shape, m, p)) : Vec3(0.0f);
    out->pdf = d2 / (std::abs(cos_l) * 4 * kPi * r * r);
    return true;
  }
  // Outside: uniform over the cone of directions the sphere subtends (pbrt-v3 §14.2.2).
  float dc = std::sqrt(dc2);
  float sin2_max = r * r / dc2, cos_max = std::sqrt(std::max(0.0f, 1 - sin2_max));
  float one_minus_cos_max = sin2_max / (1 + cos_max);  // no cancellation for small spheres
  float one_minus_cos = float(u[0]) * one_minus_cos_max;
  float cos_t = 1 - one_minus_cos, sin_t = std::sqrt(std::max(0.0f, one_minus_cos * (2 - one_minus_cos)));
  float phi = float(2 * kPi * u[1]);
  Frame f(to_c / dc);
  Vec3 wi = f.to_world({sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t});
  // Distance to the near intersection of the sampled direction with the sphere.
  float b = dot(wi, to_c), disc = std::max(0.0f, r * r - (dc2 - b * b));
  float dist = b - std::sqrt(disc);
  out->wi = wi, out->dist = dist;
  out->x = sphere_light_point(scene_, e.shape, m, c, r, ref + wi * dist);
  out->n = normalize(out->x.p - c);
  out->radiance = emitter_radiance(mat, sphere_hit(scene_, e.shape, m, out->x.p));
  out->pdf = 1.0f / (2 * kPi * one_minus_cos_max);
  return dist > 0;
}

float LightSampler::sphere_pdf(int shape, const Vec3& ref, const Vec3& p, const Vec3& n, float time) const {
  Affine m = scene_.transform(shape, time);
  Vec3 c = m.point(scene_.sphere_center(shape));
  float r = sphere_radius_at(scene_, shape, m);
  Vec3 to_c = c - ref;
  float dc2 = dot(to_c, to_c);
  if (sees_sphere_from_inside(dc2, r)) {
    Vec3 d = p - ref;
    float d2 = dot(d, d), cos_l = std::abs(dot(n, d)) / std::sqrt(d2);
    return cos_l > 0 ? d2 / (cos_l * 4 * kPi * r * r) : 0.0f;
  }
  float sin2_max = r * r / dc2, cos_max = std::sqrt(std::max(0.0f, 1 - sin2_max));
  return 1.0f / (2 * kPi * (sin2_max / (1 + cos_max)));
}

float LightSampler::pdf(const Vec3& ref, const Vec3& n, const SurfaceHit& hit, float time) const {
  // Emitters inside instances are not in the sampler: BSDF sampling alone reaches them (weight 1).
  if (hit.instance >= 0 || std::size_t(hit.shape) >= first_entry_.size()) return 0;
  int64_t first = first_entry_[hit.shape];
  if (first < 0) return 0;
  const ShapeDesc& s = scene_.desc().shapes[hit.shape];
  if (s.kind == ShapeDesc::Kind::Sphere)
    return select_pmf(ref, n, std::size_t(first)) * sphere_pdf(hit.shape, ref, hit.p, hit.ng, time);
  std::size_t e = std::size_t(first + hit.prim);
  Vec3 a, b, c;
  triangle_at(hit.shape, hit.prim, time, &a, &b, &c);
  float area = 0.5f * length(cross(b - a, c - a));
  Vec3 d = hit.p - ref;
  float d2 = dot(d, d);
  float cos_l = std::abs(dot(hit.ng, d)) / std::sqrt(d2);
  if (area <= 0 || cos_l <= 0) return 0;
  return select_pmf(ref, n, e) * d2 / (cos_l * area);
}

float LightSampler::environment_pdf(const Vec3& ref, const Vec3& n, const Vec3& w) const {
  if (!(env_irradiance_ > 0)) return 0.0f;
  return select_pmf(ref, n, environment_id()) * (map_.empty() ? 1.0f / (4 * kPi) : map_.pdf(w));
}

Vec3 LightSampler::emitted(const SurfaceHit& hit) const {
  const Material& m = scene_.desc().materials[scene_.material(hit.shape)];
  if (m.type != MaterialType::Emitter) return Vec3(0.0f);
  return (hit.front || m.two_sided) ? emitter_radiance(m, hit) : Vec3(0.0f);
}

}  // namespace pdrt
