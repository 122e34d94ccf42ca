#pragma once
// Spawning rays from surfaces without self-intersection, after pbrt-v4 (Pharr, Jakob &
// Humphreys, 4th ed., §6.8): a surface point carries a bound on its floating-point error;
// rays leave from the point offset along the geometric normal just past that bound, and a
// shadow ray runs between two such offset points, so it neither re-hits the surface it
// leaves nor the light it aims at. Unlike pbrt, Embree intersects with its own rounding, so
// the bounds built here also cover Embree's plane and sphere tests (terms in the primitive's
// size), not only the reconstruction of the point.
#include "renderer/render/ray.h"
#include "renderer/scene/transform.h"

namespace pdrt {

// gamma(n) = n u / (1 - n u), u = 2^-24: the relative bound of n rounded float operations.
constexpr float float_gamma(int n) {
  constexpr float u = 0x1.0p-24f;
  return float(n) * u / (1 - float(n) * u);
}

// A point with a per-component absolute error bound.
struct ErrorPoint {
  Vec3 p;
  Vec3 error;
};

// p on triangle (a, b, c) from barycentrics (b1, b2) (b0 = 1 - b1 - b2).
ErrorPoint triangle_point(const Vec3& a, const Vec3& b, const Vec3& c, float b1, float b2);
// The point of the sphere (centre, radius) nearest to `near` (reprojection onto the surface).
ErrorPoint sphere_point(const Vec3& centre, float radius, const Vec3& near);
// `x` carried through the affine transform m, its bound grown by the transform's rounding.
ErrorPoint transform_point(const Affine& m, const ErrorPoint& x);

// p offset along the geometric normal n, to the side of w, just past its error bound.
Vec3 offset_ray_origin(const ErrorPoint& x, const Vec3& n, const Vec3& w);

// A ray leaving the surface point x (geometric normal n) in direction dir.
Ray spawn_ray(const ErrorPoint& x, const Vec3& n, const Vec3& dir, float time);

// A shadow ray from surface point `from` to surface point `to` (both offset toward each
// other): its direction is not normalised and it ends at t = 1 - 1e-4.
Ray spawn_ray_to(const ErrorPoint& from, const Vec3& n_from, const ErrorPoint& to, const Vec3& n_to, float time);

}  // namespace pdrt
