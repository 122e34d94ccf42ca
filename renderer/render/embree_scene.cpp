#include "renderer/render/embree_scene.h"

#include "renderer/render/instance_keys.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pdrt {

namespace {

// Uniform time steps over the whole shutter [open, close] for a keyframed motion that is
// clamped outside its keys' range. Embree treats an instance as absent outside its time
// range, so the steps must cover the shutter, not just the keys. Evenly spaced keys extend
// their grid by clamped copies (exact); other keys are resampled finely enough that Embree's
// linear interpolation follows ours.
// `fine`: always resample (instances whose decomposition Embree cannot follow between keys).
std::vector<MotionKey> time_steps(const std::vector<MotionKey>& keys, float open, float close, bool fine = false) {
  constexpr int kMaxSteps = 129;
  const int n = int(keys.size());
  const float t0 = keys.front().time, t1 = keys.back().time, dt = (t1 - t0) / (n - 1);
  const float tol = 1e-6f * (1 + std::max(std::abs(open), std::abs(close)));
  bool even = !fine;
  for (int i = 0; i < n; ++i) even = even && std::abs(keys[i].time - (t0 + i * dt)) <= tol;
  if (even) {
    const int before = int(std::ceil((t0 - open) / dt - 1e-4f)), after = int(std::ceil((close - t1) / dt - 1e-4f));
    if (before + n + after <= kMaxSteps) {
      std::vector<MotionKey> out;
      for (int i = -before; i < n + after; ++i) {
        MotionKey k = interpolate(keys.data(), n, t0 + float(i) * dt);
        k.time = t0 + float(i) * dt;
        out.push_back(k);
      }
      return out;
    }
  }
  const float lo = std::min(open, t0), hi = std::max(close, t1);
  const int steps = kMaxSteps;
  std::vector<MotionKey> out(steps);
  for (int i = 0; i < steps; ++i) {
    const float t = lo + (hi - lo) * float(i) / float(steps - 1);
    out[i] = interpolate(keys.data(), n, t);
    out[i].time = t;
  }
  return out;
}

// An orthonormal pair spanning the plane normal to unit n (Duff et al. 2017), for dp/du and
// dp/dv where the uv parametrisation is degenerate.
void tangents(const Vec3& n, Vec3* a, Vec3* b) {
  const float sign = std::copysign(1.0f, n.z);
  const float p = -1.0f / (sign + n.z), q = n.x * n.y * p;
  *a = Vec3(1 + sign * n.x * n.x * p, sign * q, -sign * n.x);
  *b = Vec3(q, sign + n.y * n.y * p, -n.y);
}

Affine from_row_major(const float m[12]) {
  Affine a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.m[r][c] = m[r * 4 + c];
  return a;
}

}  // namespace

RTCGeometry EmbreeScene::make_geometry(const Shape& s) const {
  RTCDevice dev = device_.get();
  if (s.sphere) {
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 16, 1));
    v[0] = s.center.x, v[1] = s.center.y, v[2] = s.center.z, v[3] = s.radius;
    rtcCommitGeometry(g);
    return g;
  }
  RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, s.positions.size()));
  for (std::size_t i = 0; i < s.positions.size(); ++i)
    v[3 * i] = s.positions[i].x, v[3 * i + 1] = s.positions[i].y, v[3 * i + 2] = s.positions[i].z;
  auto* ix = static_cast<uint32_t*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, s.indices.size() / 3));
  std::copy(s.indices.begin(), s.indices.end(), ix);
  rtcCommitGeometry(g);
  return g;
}

void EmbreeScene::add_shape(Shape& s, const ShapeDesc& d) {
  const Affine& m = d.transform;
  s.desc = &d;
  if (d.kind == ShapeDesc::Kind::Sphere) {
    s.sphere = true;
    s.center = m.point(d.center);
    // Spheres stay spheres: a non-uniform scale is replaced by its geometric mean.
    s.radius = d.radius * std::cbrt(std::abs(m.determinant()));
    s.to_world = m, s.to_object = m.inverse(), s.object_radius = d.radius;
  } else {
    s.positions.reserve(d.mesh.positions.size());
    for (const Vec3& p : d.mesh.positions) s.positions.push_back(m.point(p));
    for (const Vec3& n : d.mesh.normals) s.normals.push_back(normalize(m.normal(n)));
    s.indices = d.mesh.indices;
    s.uvs = d.mesh.uvs;
    triangles_ += s.indices.size() / 3;
  }
}

// An instance of `child` keyframed over the shutter: world(t) = interpolate(motion, t) *
// static_part, each time step decomposed for Embree (instance_keys.h).
RTCGeometry EmbreeScene::make_moving_instance(RTCScene child, const std::vector<MotionKey>& motion,
                                              const Affine& static_part) const {
  const CameraDesc& c = desc_.camera;
  const float span = c.shutter_close - c.shutter_open;
  const bool fine = !embree_follows_keys(motion, static_part);
  std::vector<MotionKey> steps =
      span > 0 ? time_steps(motion, c.shutter_open, c.shutter_close, fine)
               : std::vector<MotionKey>{interpolate(motion.data(), int(motion.size()), c.shutter_open)};
  RTCGeometry inst = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(inst, child);
  rtcSetGeometryTimeStepCount(inst, unsigned(steps.size()));
  if (steps.size() > 1)
    rtcSetGeometryTimeRange(inst, (steps.front().time - c.shutter_open) / span,
                            (steps.back().time - c.shutter_open) / span);
  Quat previous;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    InstanceKey key = instance_key(steps[k], static_part);
    Quat& q = key.rotate;
    // Neighbouring steps on one hemisphere: the slerp between them takes the short arc.
    if (k > 0 && q.w * previous.w + q.x * previous.x + q.y * previous.y + q.z * previous.z < 0)
      q = {-q.w, -q.x, -q.y, -q.z};
    previous = q;
    RTCQuaternionDecomposition d;
    rtcInitQuaternionDecomposition(&d);
    rtcQuaternionDecompositionSetScale(&d, key.scale[0], key.scale[1], key.scale[2]);
    rtcQuaternionDecompositionSetSkew(&d, key.skew[0], key.skew[1], key.skew[2]);
    rtcQuaternionDecompositionSetShift(&d, key.shift[0], key.shift[1], key.shift[2]);
    rtcQuaternionDecompositionSetQuaternion(&d, q.w, q.x, q.y, q.z);
    rtcQuaternionDecompositionSetTranslation(&d, key.translate.x, key.translate.y, key.translate.z);
    rtcSetGeometryTransformQuaternion(inst, unsigned(k), &d);
  }
  rtcCommitGeometry(inst);
  return inst;
}

EmbreeScene::EmbreeScene(const SceneDesc& desc, const EmbreeDevice& device) : desc_(desc), device_(device) {
  RTCDevice dev = device.get();
  scene_ = rtcNewScene(dev);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  std::size_t total = desc.shapes.size();
  for (const PrototypeDesc& p : desc.prototypes) total += p.shapes.size();
  shapes_.resize(total);
  for (std::size_t i = 0; i < desc.shapes.size(); ++i) {
    const ShapeDesc& d = desc.shapes[i];
    Shape& s = shapes_[i];
    add_shape(s, d);
    RTCGeometry g = make_geometry(s);
    if (d.motion.empty()) {
      rtcAttachGeometryByID(scene_, g, unsigned(i));
      rtcReleaseGeometry(g);
      continue;
    }
    s.child = rtcNewScene(dev);
    rtcAttachGeometryByID(s.child, g, 0);
    rtcReleaseGeometry(g);
    rtcCommitScene(s.child);
    // Keyframe times are in shutter units; rays carry time normalised to the shutter. An
    // instantaneous shutter sees the motion at its one time, as a single step.
    const CameraDesc& c = desc.camera;
    const float span = c.shutter_close - c.shutter_open;
    std::vector<MotionKey> steps =
        span > 0 ? time_steps(d.motion, c.shutter_open, c.shutter_close)
                 : std::vector<MotionKey>{interpolate(d.motion.data(), int(d.motion.size()), c.shutter_open)};
    RTCGeometry inst = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(inst, s.child);
    rtcSetGeometryTimeStepCount(inst, unsigned(steps.size()));
    if (steps.size() > 1)
      rtcSetGeometryTimeRange(inst, (steps.front().time - c.shutter_open) / span,
                              (steps.back().time - c.shutter_open) / span);
    for (std::size_t k = 0; k < steps.size(); ++k) {
      RTCQuaternionDecomposition q;
      rtcInitQuaternionDecomposition(&q);
      rtcQuaternionDecompositionSetScale(&q, steps[k].scale.x, steps[k].scale.y, steps[k].scale.z);
      rtcQuaternionDecompositionSetQuaternion(&q, steps[k].rotate.w, steps[k].rotate.x, steps[k].rotate.y,
                                              steps[k].rotate.z);
      rtcQuaternionDecompositionSetTranslation(&q, steps[k].translate.x, steps[k].translate.y, steps[k].translate.z);
      rtcSetGeometryTransformQuaternion(inst, unsigned(k), &q);
    }
    rtcCommitGeometry(inst);
    rtcAttachGeometryByID(scene_, inst, unsigned(i));
    s.instance = inst;  // keeps a reference for transform queries (released in the destructor)
  }
  // Prototypes: one child scene each, committed once, geometry IDs the prototype's shape
  // order. Their shapes' motion is not supported (one level of instancing; the loader refuses it).
  std::size_t next = desc.shapes.size();
  for (const PrototypeDesc& p : desc.prototypes) {
    prototype_first_.push_back(int(next));
    RTCScene child = rtcNewScene(dev);
    rtcSetSceneFlags(child, RTC_SCENE_FLAG_ROBUST);
    for (std::size_t k = 0; k < p.shapes.size(); ++k, ++next) {
      add_shape(shapes_[next], p.shapes[k]);
      RTCGeometry g = make_geometry(shapes_[next]);
      rtcAttachGeometryByID(child, g, unsigned(k));
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(child);
    prototypes_.push_back(child);
  }
  instances_.resize(desc.instances.size());
  for (std::size_t j = 0; j < desc.instances.size(); ++j) {
    const InstanceDesc& d = desc.instances[j];
    Instance& in = instances_[j];
    RTCScene child = prototypes_[std::size_t(d.prototype)];
    RTCGeometry inst;
    if (d.motion.empty()) {
      inst = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(inst, child);
      rtcSetGeometryTimeStepCount(inst, 1);
      float m[12];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m[r * 4 + c] = d.transform.m[r][c];
      rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
      rtcCommitGeometry(inst);
      in.to_world = d.transform, in.to_prototype = d.transform.inverse();
    } else {
      inst = make_moving_instance(child, d.motion, d.transform);
      in.geometry = inst;
      rtcRetainGeometry(inst);
    }
    rtcAttachGeometryByID(scene_, inst, unsigned(desc.shapes.size() + j));
    rtcReleaseGeometry(inst);
  }
  rtcCommitScene(scene_);
  device.check();

  RTCLinearBounds lb;
  rtcGetSceneLinearBounds(scene_, &lb);
  Vec3 lo(std::min(lb.bounds0.lower_x, lb.bounds1.lower_x), std::min(lb.bounds0.lower_y, lb.bounds1.lower_y),
          std::min(lb.bounds0.lower_z, lb.bounds1.lower_z));
  Vec3 hi(std::max(lb.bounds0.upper_x, lb.bounds1.upper_x), std::max(lb.bounds0.upper_y, lb.bounds1.upper_y),
          std::max(lb.bounds0.upper_z, lb.bounds1.upper_z));
  if ((desc.shapes.empty() && desc.instances.empty()) || !(hi.x >= lo.x)) lo = hi = Vec3(0.0f);
  bounds_radius_ = std::max(length(hi - lo) * 0.5f, 1e-3f);
}

EmbreeScene::~EmbreeScene() {
  for (Shape& s : shapes_) {
    if (s.instance) rtcReleaseGeometry(s.instance);
    if (s.child) rtcReleaseScene(s.child);
  }
  for (Instance& in : instances_)
    if (in.geometry) rtcReleaseGeometry(in.geometry);
  for (RTCScene p : prototypes_) rtcReleaseScene(p);
  if (scene_) rtcReleaseScene(scene_);
}

Affine EmbreeScene::transform(int shape, float time) const {
  const Shape& s = shapes_[shape];
  if (!s.instance) return Affine{};
  float m[12];
  rtcGetGeometryTransform(s.instance, time, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
  return from_row_major(m);
}

Affine EmbreeScene::instance_transform(int i, float time) const {
  const Instance& in = instances_[std::size_t(i)];
  if (!in.geometry) return in.to_world;
  float m[12];
  rtcGetGeometryTransform(in.geometry, time, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, m);
  return from_row_major(m);
}

Affine EmbreeScene::hit_transform(const SurfaceHit& hit, float time) const {
  if (hit.instance >= 0) return instance_transform(hit.instance, time);
  return transform(hit.shape, time);
}

bool EmbreeScene::intersect(const Ray& ray, SurfaceHit* hit) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh;
  rh.ray.org_x = ray.org.x, rh.ray.org_y = ray.org.y, rh.ray.org_z = ray.org.z;
  rh.ray.dir_x = ray.dir.x, rh.ray.dir_y = ray.dir.y, rh.ray.dir_z = ray.dir.z;
  rh.ray.tnear = ray.tmin, rh.ray.tfar = ray.tmax, rh.ray.time = ray.time;
  rh.ray.mask = ~0u, rh.ray.flags = 0, rh.ray.id = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  finish_hit(ray, rh.hit.instID[0], rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v,
             Vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z), rh.ray.tfar, hit);
  return true;
}

void EmbreeScene::intersect4(const Ray* rays, const bool* live, SurfaceHit* hits, bool* found) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // camera rays of one pixel
  alignas(16) RTCRayHit4 rh;
  alignas(16) int valid[4];
  for (int k = 0; k < 4; ++k) {
    const Ray& r = rays[k];
    valid[k] = live[k] ? -1 : 0;
    rh.ray.org_x[k] = r.org.x, rh.ray.org_y[k] = r.org.y, rh.ray.org_z[k] = r.org.z;
    rh.ray.dir_x[k] = r.dir.x, rh.ray.dir_y[k] = r.dir.y, rh.ray.dir_z[k] = r.dir.z;
    rh.ray.tnear[k] = r.tmin, rh.ray.tfar[k] = r.tmax, rh.ray.time[k] = r.time;
    rh.ray.mask[k] = ~0u, rh.ray.flags[k] = 0, rh.ray.id[k] = unsigned(k);
    rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect4(valid, scene_, &ctx, &rh);
  for (int k = 0; k < 4; ++k) {
    found[k] = live[k] && rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
    if (found[k])
      finish_hit(rays[k], rh.hit.instID[0][k], rh.hit.geomID[k], rh.hit.primID[k], rh.hit.u[k], rh.hit.v[k],
                 Vec3(rh.hit.Ng_x[k], rh.hit.Ng_y[k], rh.hit.Ng_z[k]), rh.ray.tfar[k], &hits[k]);
  }
}

void EmbreeScene::finish_hit(const Ray& ray, unsigned inst_id, unsigned geom_id, unsigned prim_id, float u, float v,
                             const Vec3& embree_ng, float t, SurfaceHit* hit) const {
  const bool inst = inst_id != RTC_INVALID_GEOMETRY_ID;
  const unsigned n_shapes = unsigned(desc_.shapes.size());
  // Top-level IDs past the scene's shapes are prototype instances: geom_id is the shape's
  // index within the prototype.
  const int instance = inst && inst_id >= n_shapes ? int(inst_id - n_shapes) : -1;
  const int shape = instance >= 0
                        ? prototype_first_[std::size_t(desc_.instances[std::size_t(instance)].prototype)] + int(geom_id)
                        : int(inst ? inst_id : geom_id);
  const Shape& s = shapes_[shape];
  hit->t = t;
  hit->shape = shape;
  hit->instance = instance;
  hit->prim = int(prim_id);
  // The hit point is rebuilt from the primitive (pbrt-v4 §6.8): org + t dir carries an
  // error that grows with |org| + t, the reprojected point one bounded by the surface's own size.
  Affine m, inv;
  if (instance >= 0 && !instances_[std::size_t(instance)].geometry) {
    m = instances_[std::size_t(instance)].to_world, inv = instances_[std::size_t(instance)].to_prototype;
  } else if (inst) {
    m = hit_transform(*hit, ray.time), inv = m.inverse();
  }
  ErrorPoint x;
  Vec3 ng, ns;
  if (s.sphere) {
    ng = ns = embree_ng;  // centre to hit, instance space
    const Vec3 near = ray.org + ray.dir * t;
    x = sphere_point(s.center, s.radius, inst ? inv.point(near) : near);
  } else {
    const uint32_t* tri = &s.indices[3 * std::size_t(hit->prim)];
    const Vec3 &a = s.positions[tri[0]], &b = s.positions[tri[1]], &c = s.positions[tri[2]];
    x = triangle_point(a, b, c, u, v);
    ng = cross(b - a, c - a);  // counter-clockwise winding is the front face
    if (!s.normals.empty()) {
      ns = s.normals[tri[0]] * (1 - u - v) + s.normals[tri[1]] * u + s.normals[tri[2]] * v;
    } else {
      ns = ng;
    }
  }
  hit->p_local = x.p;
  if (inst) {
    x = transform_point(m, x);
    ng = inv.transpose_vector(ng), ns = inv.transpose_vector(ns);
  }
  hit->bary_u = u, hit->bary_v = v;
  hit->p = x.p;
  hit->p_error = x.error;
  ng = normalize(ng), ns = normalize(ns);
  if (!is_finite(ns) || dot(ns, ns) == 0) ns = ng;
  hit->ng = ng;
  hit->ns = dot(ns, ng) < 0 ? -ns : ns;
  hit->front = dot(ray.dir, ng) < 0;
}

void EmbreeScene::texture_coords(SurfaceHit* hit, float time) const {
  const Shape& s = shapes_[hit->shape];
  Vec3 dpdu, dpdv;
  if (s.sphere) {
    // Object space, +y the pole: u = azimuth / 2 pi from +x toward +z, v = polar angle from -y / pi
    // (v = 0 at -y, 1 at +y), as pbrt-v4's sphere with y in place of z.
    Vec3 d = s.to_object.vector(hit->p_local - s.center);
    const float len = length(d);
    d = len > 0 ? d / len : Vec3(0, 1, 0);
    float phi = std::atan2(d.z, d.x);
    if (phi < 0) phi += 2 * kPi;
    const float theta = std::acos(std::clamp(-d.y, -1.0f, 1.0f));  // from -y
    hit->u = phi / (2 * kPi);
    hit->v = theta / kPi;
    // dp/du = 2 pi (-z, 0, x) r; dp/dv = pi r (sin(theta) direction toward +y along the meridian).
    const float r = s.object_radius, sin_t = std::sqrt(std::max(0.0f, 1 - d.y * d.y));
    dpdu = s.to_world.vector(Vec3(-d.z, 0, d.x) * (2 * kPi * r));
    const Vec3 rho = sin_t > 0 ? Vec3(d.x, 0, d.z) / sin_t : Vec3(1, 0, 0);
    dpdv = s.to_world.vector((Vec3(0, sin_t, 0) - rho * d.y) * (kPi * r));
  } else {
    const uint32_t* tri = &s.indices[3 * std::size_t(hit->prim)];
    const Vec3 &a = s.positions[tri[0]], &b = s.positions[tri[1]], &c = s.positions[tri[2]];
    const float b1 = hit->bary_u, b2 = hit->bary_v;
    // Without per-vertex uvs, the barycentrics: vertex 0 -> (0, 0), 1 -> (1, 0), 2 -> (0, 1).
    std::array<float, 2> t0{0, 0}, t1{1, 0}, t2{0, 1};
    if (!s.uvs.empty()) t0 = s.uvs[tri[0]], t1 = s.uvs[tri[1]], t2 = s.uvs[tri[2]];
    hit->u = t0[0] * (1 - b1 - b2) + t1[0] * b1 + t2[0] * b2;
    hit->v = t0[1] * (1 - b1 - b2) + t1[1] * b1 + t2[1] * b2;
    // pbrt-v4 §6.5.3: solve p_i - p_2 = (u_i - u_2) dp/du + (v_i - v_2) dp/dv.
    const float du02 = t0[0] - t2[0], dv02 = t0[1] - t2[1], du12 = t1[0] - t2[0], dv12 = t1[1] - t2[1];
    const Vec3 dp02 = a - c, dp12 = b - c;
    const float det = du02 * dv12 - dv02 * du12;
    bool ok = std::abs(det) > 1e-12f;
    if (ok) {
      dpdu = (dp02 * dv12 - dp12 * dv02) / det;
      dpdv = (dp12 * du02 - dp02 * du12) / det;
      ok = is_finite(dpdu) && is_finite(dpdv) && !is_black(cross(dpdu, dpdv));
    }
    if (!ok) tangents(normalize(cross(b - a, c - a)), &dpdu, &dpdv);
  }
  if (s.instance || hit->instance >= 0) {
    const Affine m = hit_transform(*hit, time);
    dpdu = m.vector(dpdu), dpdv = m.vector(dpdv);
  }
  hit->dpdu = dpdu, hit->dpdv = dpdv;
}

bool EmbreeScene::occluded(const Ray& ray) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay r;
  r.org_x = ray.org.x, r.org_y = ray.org.y, r.org_z = ray.org.z;
  r.dir_x = ray.dir.x, r.dir_y = ray.dir.y, r.dir_z = ray.dir.z;
  r.tnear = ray.tmin, r.tfar = ray.tmax, r.time = ray.time;
  r.mask = ~0u, r.flags = 0, r.id = 0;
  rtcOccluded1(scene_, &ctx, &r);
  return r.tfar < 0;  // Embree sets tfar to -inf on a hit
}

}  // namespace pdrt
