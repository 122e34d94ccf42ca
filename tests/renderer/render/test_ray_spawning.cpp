// Rays spawned from surfaces (ray_spawn.h): a scene renders the same wherever it is placed
// and at whatever scale, because hit points are reprojected with an error bound and rays
// leave, and shadow rays arrive, just past that bound. The defects these catch lived away
// from the origin: self-shadowing lights, acne on distant spheres.
#include "renderer/render/ray_spawn.h"
#include "renderer/render/thin_lens_camera.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;
using namespace pdrt::test;

namespace {

const std::vector<Placement> kPlacements = {{{0, 0, 0}, 1},    {{10, 0, 0}, 1},         {{1e3f, -1e3f, 0}, 1},
                                            {{1e5f, 0, 0}, 1}, {{0, 0, 1e5f}, 1},       {{0, 0, 0}, 1e-3f},
                                            {{0, 0, 0}, 1e3f}, {{1e3f, 0, 1e3f}, 1e3f}, {{-10, 5, 3}, 1e-3f}};

// Looking straight down at the plane y = 0 from `height` with a 90° field: pixel (x, y)
// sees the plane point below its centre.
SceneDesc looking_down(const Placement& at, int w, int spp, float height) {
  SceneDesc s = base_scene(w, w, spp);
  s.camera.position = at.point({0, height, 0}), s.camera.look_at = at.point({0, 0, 0});
  s.camera.up = {0, 0, -1}, s.camera.vfov_deg = 90;
  s.integrator.max_depth = 1;  // direct light only
  return s;
}

// The plane point seen by the centre of pixel (x, y) in looking_down (canonical units).
Vec3 plane_point(int x, int y, int w, float height) {
  return {float(((x + 0.5) / w - 0.5) * 2 * height), 0, float(((y + 0.5) / w - 0.5) * 2 * height)};
}

}  // namespace

// A diffuse plane 1 unit under a one-sided square light reads the analytic value at the
// pixel under the light's centre (form factor of a square, 0.4789 for albedo 1 and L = 1),
// wherever the scene is and at every scale.
TEST(RaySpawning, PlaneUnderQuadLightIsTheSameAtEveryPlacement) {
  const int W = 9;
  const float h = 1, rho = 0.5f, Le = 1;
  // Unit square light at height h facing down: F = 4 * corner form factor of a 0.5 square.
  const double X = 0.5 / h, a = std::sqrt(1 + X * X);
  const double F = 4 * (2 * X / a * std::atan(X / a)) / (2 * M_PI);
  const double expected = rho * Le * F;
  for (const Placement& at : kPlacements) {
    SceneDesc s = looking_down(at, W, 64, 0.05f);
    s.shapes.push_back(quad(at.point({-5, 0, -5}), at.vector({0, 0, 10}), at.vector({10, 0, 0}),
                            add_material(s, diffuse(rho))));  // normal +y
    s.shapes.push_back(quad(at.point({-0.5f, h, -0.5f}), at.vector({1, 0, 0}), at.vector({0, 0, 1}),
                            add_material(s, emitter(Le))));  // faces down
    Image im = render_quietly(s).image;
    double sum = 0;
    for (int y = 0; y < W; ++y)
      for (int x = 0; x < W; ++x) sum += mean_rgb(im, x, y);
    // The camera sees a 0.1-wide patch: F varies by < 0.1 % over it.
    EXPECT_NEAR(sum / (W * W), expected, 0.02 * expected) << describe(at);
  }
}

// A sphere light of radius 0.5 at height 1 over a diffuse plane: radiance rho L r^2 / d^3
// at a plane point at distance d from the centre (a sphere above the horizon acts as a point
// of intensity L pi r^2). Checked at several pixels, at every placement.
TEST(RaySpawning, PlaneUnderSphereLightMatchesTheAnalyticValueAtEveryPlacement) {
  const int W = 16;
  const float rho = 0.5f, Le = 4, r = 0.5f, height = 0.3f;
  for (const Placement& at : kPlacements) {
    SceneDesc s = looking_down(at, W, 256, height);
    s.shapes.push_back(
        quad(at.point({-5, 0, -5}), at.vector({0, 0, 10}), at.vector({10, 0, 0}), add_material(s, diffuse(rho))));
    s.shapes.push_back(sphere(at.point({0, 1, 0}), r * at.scale, add_material(s, emitter(Le))));
    Image im = render_quietly(s).image;
    double err = 0, total = 0;
    for (int y = 1; y < W; y += 3)
      for (int x = 1; x < W; x += 3) {
        const Vec3 p = plane_point(x, y, W, height);
        const double d = length(Vec3(0, 1, 0) - p);
        const double expected = rho * Le * r * r / (d * d * d);
        err += std::abs(mean_rgb(im, x, y) - expected), total += expected;
      }
    EXPECT_LT(err / total, 0.03) << describe(at);  // mean relative error under 3 %
  }
}

// A diffuse unit sphere (albedo 0.5) in a white furnace reads 0.5 when framed from 60 and
// from 6000 units away: the same image, without acne from hit points far from the origin.
TEST(RaySpawning, DistantSphereInAFurnaceShowsItsAlbedo) {
  const int W = 24;
  for (float distance : {6.0f, 60.0f, 6000.0f, 6e4f})
    for (const Vec3& centre : {Vec3(0, 0, 0), Vec3(3e3f, -2e3f, 1e3f)}) {
      SceneDesc s = base_scene(W, W, 16);
      s.camera.position = centre + Vec3(0, 0, distance), s.camera.look_at = centre;
      s.camera.vfov_deg = float(2 * std::atan(1.5 / distance) * 180 / M_PI);
      s.environment.radiance = Vec3(1.0f);
      s.integrator.max_depth = 1;
      s.shapes.push_back(sphere(centre, 1, add_material(s, diffuse(0.5f))));
      Image im = render_quietly(s).image;
      double sum = 0, worst = 0;
      int n = 0;
      for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x) {
          const double dx = x + 0.5 - W / 2.0, dy = y + 0.5 - W / 2.0;
          if (dx * dx + dy * dy > 0.25 * (W / 3.0) * (W / 3.0)) continue;  // inner half of the disc
          const double v = mean_rgb(im, x, y);
          sum += v, ++n, worst = std::max(worst, std::abs(v - 0.5));
        }
      ASSERT_GT(n, 20);
      EXPECT_NEAR(sum / n, 0.5, 0.01) << "distance " << distance << " centre x " << centre.x;
      EXPECT_LT(worst, 0.1) << "distance " << distance << " centre x " << centre.x << " (acne)";
    }
}

// The offset origin lies outside the point's error box on the side of w, so a ray leaving
// there cannot start behind the surface it leaves.
TEST(RaySpawning, OffsetOriginLeavesTheErrorBoxOnTheSideOfTheDirection) {
  for (float mag : {1e-3f, 1.0f, 1e3f, 1e5f}) {
    const Vec3 a(mag, -mag, 0.5f * mag), b = a + Vec3(1, 0, 0), c = a + Vec3(0, 0, 1);
    const ErrorPoint x = triangle_point(a, b, c, 0.3f, 0.3f);
    const Vec3 n = normalize(cross(c - a, b - a));
    for (float side : {1.0f, -1.0f}) {
      const Vec3 o = offset_ray_origin(x, n, n * side);
      // Distance of o from the plane through x, against the box's extent along n.
      const double along = double(o.x - x.p.x) * n.x + double(o.y - x.p.y) * n.y + double(o.z - x.p.z) * n.z;
      const double box = std::abs(n.x) * x.error.x + std::abs(n.y) * x.error.y + std::abs(n.z) * x.error.z;
      EXPECT_GE(along * side, box) << "magnitude " << mag;
      EXPECT_GT(box, 0);
    }
  }
}
