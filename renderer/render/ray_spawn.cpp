#include "renderer/render/ray_spawn.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace {

Vec3 abs3(const Vec3& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }

}  // namespace

ErrorPoint triangle_point(const Vec3& a, const Vec3& b, const Vec3& c, float b1, float b2) {
  const float b0 = 1 - b1 - b2;
  ErrorPoint x;
  x.p = a * b0 + b * b1 + c * b2;
  // pbrt-v4 §6.8.4: the barycentric sum is off by gamma(7) of its terms' magnitudes. Embree's
  // plane test rounds in the vertices' offsets from the ray origin, in every direction (a
  // point exactly on an axis-aligned plane has no error along its normal, but Embree can
  // still find it at t = 0): a term in the longest edge, in every component.
  const float extent = std::max({length(b - a), length(c - a), length(c - b)});
  x.error = (abs3(a * b0) + abs3(b * b1) + abs3(c * b2)) * float_gamma(7) + Vec3(extent * float_gamma(8));
  return x;
}

ErrorPoint sphere_point(const Vec3& centre, float radius, const Vec3& near) {
  Vec3 d = near - centre;
  const float len = length(d);
  d = len > 0 ? d * (radius / len) : Vec3(0, 0, radius);
  ErrorPoint x;
  x.p = centre + d;
  // pbrt-v4 §6.8.5: the reprojected offset is off by gamma(5) of itself; adding the centre
  // rounds once more; Embree's quadratic rounds in the radius (the radius term).
  x.error = abs3(d) * float_gamma(5) + (abs3(centre) + abs3(d)) * float_gamma(2) + Vec3(radius * float_gamma(8));
  return x;
}

ErrorPoint transform_point(const Affine& m, const ErrorPoint& x) {
  ErrorPoint y;
  y.p = m.point(x.p);
  // pbrt-v4 §6.8.6, Transform of a Point3fi: rounding of the product plus the input's
  // bound carried through |M|. Doubled: Embree maps the spawned origin back by M^-1.
  for (int r = 0; r < 3; ++r) {
    float mag = std::abs(m.m[r][3]), carried = 0;
    for (int c = 0; c < 3; ++c) {
      mag += std::abs(m.m[r][c] * x.p[c]);
      carried += std::abs(m.m[r][c]) * x.error[c];
    }
    y.error[r] = 2 * (float_gamma(3) * mag + (1 + float_gamma(3)) * carried);
  }
  return y;
}

Vec3 offset_ray_origin(const ErrorPoint& x, const Vec3& n, const Vec3& w) {
  const float d = dot(abs3(n), x.error);
  Vec3 offset = n * d;
  if (dot(w, n) < 0) offset = -offset;
  Vec3 po = x.p + offset;
  // The sum may round back toward the surface: step one float further away.
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0)
      po[i] = std::nextafter(po[i], INFINITY);
    else if (offset[i] < 0)
      po[i] = std::nextafter(po[i], -INFINITY);
  }
  return po;
}

Ray spawn_ray(const ErrorPoint& x, const Vec3& n, const Vec3& dir, float time) {
  Ray r;
  r.org = offset_ray_origin(x, n, dir);
  r.dir = dir;
  r.tmin = 0, r.tmax = 1e30f;
  r.time = time;
  return r;
}

Ray spawn_ray_to(const ErrorPoint& from, const Vec3& n_from, const ErrorPoint& to, const Vec3& n_to, float time) {
  constexpr float kShadowEpsilon = 1e-4f;  // pbrt-v4's ShadowEpsilon
  Ray r;
  r.org = offset_ray_origin(from, n_from, to.p - from.p);
  const Vec3 target = offset_ray_origin(to, n_to, r.org - to.p);
  r.dir = target - r.org;
  r.tmin = 0, r.tmax = 1 - kShadowEpsilon;
  r.time = time;
  return r;
}

}  // namespace pdrt
