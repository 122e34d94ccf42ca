// The orthographic camera (pbrt-v4 §5.2.1): parallel rays, a film of fixed world size
// whatever the distance, and thin-lens depth of field with a circle of confusion that
// depends only on the lens radius and the distance to the plane of focus.
#include "renderer/render/texture_footprint.h"
#include "renderer/render/thin_lens_camera.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;
using namespace pdrt::test;

namespace {

CameraDesc ortho_camera(float height) {
  CameraDesc c;
  c.projection = CameraDesc::Projection::Orthographic;
  c.position = {0, 0, 0}, c.look_at = {0, 0, -1};
  c.ortho_height = height;
  return c;
}

// Horizontal spread of the image's brightness: sqrt of the variance of x.
double spread_x(const Image& im, double* cx) {
  double w = 0, sx = 0, sxx = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      double v = mean_rgb(im, x, y);
      w += v, sx += v * (x + 0.5), sxx += v * (x + 0.5) * (x + 0.5);
    }
  *cx = sx / w;
  return std::sqrt(sxx / w - (sx / w) * (sx / w));
}

}  // namespace

// Film 80x40 with ortho_height 4: the window is [-4, 4] x [-2, 2], 10 pixels per unit; a
// point maps to ((x + 4) 10, (2 - y) 10) at any depth, and mirrored in x with flip_x.
TEST(OrthographicCamera, ProjectsOffAxisPointsLinearlyAtAnyDepth) {
  CameraDesc c = ortho_camera(4);
  for (float z : {-0.5f, -7.0f, -300.0f}) {
    ThinLensCamera cam(c, 80, 40);
    auto p = cam.project({1.5f, -0.5f, z});
    EXPECT_NEAR(p[0], 55, 1e-4) << z;
    EXPECT_NEAR(p[1], 25, 1e-4) << z;
    auto q = cam.project({-3.9f, 1.8f, z});
    EXPECT_NEAR(q[0], 1, 1e-4) << z;
    EXPECT_NEAR(q[1], 2, 1e-4) << z;
  }
  c.flip_x = true;
  auto p = ThinLensCamera(c, 80, 40).project({1.5f, -0.5f, -7});
  EXPECT_NEAR(p[0], 25, 1e-4);
  EXPECT_NEAR(p[1], 25, 1e-4);
}

// Pinhole rays are parallel to the view direction and start on the film's world rectangle:
// the ray through a point's projection passes through the point.
TEST(OrthographicCamera, RayThroughProjectedPointIsParallelAndHitsIt) {
  CameraDesc c = ortho_camera(3);
  c.position = {1, 2, 3}, c.look_at = {0, 0.5f, -1};
  ThinLensCamera cam(c, 200, 100);
  const Vec3 forward = normalize(c.look_at - c.position);
  for (Vec3 w : {Vec3(0.3f, 0.2f, -2), Vec3(-1.2f, 1.9f, -4)}) {
    auto f = cam.project(w);
    Ray r = cam.generate(f[0], f[1], {0.5, 0.5}, 0);
    EXPECT_NEAR(dot(r.dir, forward), 1.0f, 1e-6f);
    const Vec3 off = w - r.org;
    EXPECT_NEAR(length(off - r.dir * dot(off, r.dir)), 0.0f, 1e-5f);  // the point is on the ray
  }
}

// An emitting square facing the camera, its edges on pixel boundaries (16 pixels per unit,
// x in [-1, 0.5], y in [-0.75, 1.25]: columns 16..39, rows 12..43), covers exactly 24 x 32
// pixels at 3 and at 30 units: each of those pixels is 1, every other 0 (box filter, one
// pixel's samples stay in it).
TEST(OrthographicCamera, SquareCoversTheSamePixelsAtAnyDistance) {
  for (float dist : {3.0f, 30.0f}) {
    SceneDesc s = base_scene(64, 64, 4);
    s.camera = ortho_camera(4);
    s.camera.position = {0, 0, dist};
    s.camera.look_at = {0, 0, 0};
    s.shapes.push_back(quad({-1, -0.75f, 0}, {1.5f, 0, 0}, {0, 2, 0}, add_material(s, emitter(1.0f))));
    Image im = render_quietly(s).image;
    int lit = 0, wrong = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const bool inside = x >= 16 && x < 40 && y >= 12 && y < 44;
        const double v = mean_rgb(im, x, y);
        lit += v > 0.5;
        wrong += inside ? std::abs(v - 1) > 1e-6 : v != 0;
      }
    EXPECT_EQ(lit, 24 * 32) << dist;
    EXPECT_EQ(wrong, 0) << dist;
  }
}

// pbrt-v4's OrthographicCamera depth of field: the ray from film point o moved by lens offset
// a aims at o + f forward, so at depth d it is a (1 - d/f) off o: a point at depth d images
// to a disk of radius A |1 - d/f| in scene units (A |1 - d/f| H / ortho_height pixels) on the
// point's own projection, whatever the camera's distance otherwise. A uniform disk of radius
// R has a horizontal standard deviation of R/2.
TEST(OrthographicCamera, OffFocusPointSpreadsOverItsCircleOfConfusion) {
  const float A = 0.2f, f = 5, d = 2.5f, height = 1, H = 64;
  SceneDesc s = base_scene(64, 64, 256);
  s.camera = ortho_camera(height);
  s.camera.aperture_radius = A, s.camera.focus_distance = f;
  s.shapes.push_back(sphere({0.125f, 0, -d}, 0.01f, add_material(s, emitter(1.0f))));
  Image im = render_quietly(s).image;
  double cx, sd = spread_x(im, &cx);
  const double R = A * std::abs(1 - d / f) * H / height;                          // 6.4 px
  const double point_sd = 0.01 * H / height / 2;                                  // the sphere's own disk
  const double expected = std::sqrt(R * R / 4 + point_sd * point_sd + 1.0 / 12);  // + the pixel's box
  EXPECT_NEAR(cx, 32 + 0.125 * H / height, 0.2);
  EXPECT_NEAR(sd, expected, 0.05 * expected) << "R = " << R << " px";
}

// At the focus distance the same point stays within the four pixels around its projection.
TEST(OrthographicCamera, PointAtFocusDistanceStaysSharp) {
  SceneDesc s = base_scene(64, 64, 64);
  s.camera = ortho_camera(1);
  s.camera.aperture_radius = 0.2f, s.camera.focus_distance = 5;
  s.shapes.push_back(sphere({0, 0, -5}, 0.01f, add_material(s, emitter(1.0f))));
  Image im = render_quietly(s).image;
  double inside = 0, total = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double v = mean_rgb(im, x, y);
      total += v;
      if ((x == 31 || x == 32) && (y == 31 || y == 32)) inside += v;
    }
  EXPECT_GT(total, 0);
  EXPECT_EQ(inside, total) << "light outside the four pixels around the point";
}

// The texture footprint of the orthographic camera: neighbouring pixels' rays are parallel,
// one pixel (ortho_height / H scene units) to the side, so on a plane facing the camera
// du/dx = pixel / |dp/du| at any distance, and on a plane turned by 60 degrees about the
// vertical the horizontal footprint stretches by 1 / cos 60 = 2. At 1 spp the spp scale is 1.
TEST(OrthographicCamera, TextureFootprintIsOnePixelOfParallelRays) {
  CameraDesc c = ortho_camera(2);  // 64 x 32: 1/16 scene unit per pixel
  TextureFootprint fp(c, 64, 32, 1);
  SurfaceHit h;
  h.ng = {0, 0, 1};
  h.dpdu = {4, 0, 0}, h.dpdv = {0, 4, 0};
  for (float z : {-1.0f, -50.0f}) {
    h.p = {0.3f, -0.2f, z};
    TextureCoords tc = fp.at(h);
    EXPECT_NEAR(tc.dudx, 1.0f / 64, 1e-6f) << z;
    EXPECT_NEAR(tc.dvdy, 1.0f / 64, 1e-6f) << z;
    EXPECT_NEAR(tc.dvdx, 0, 1e-7f) << z;
  }
  const float a = 60 * kPi / 180;
  h.ng = {std::sin(a), 0, std::cos(a)};
  h.dpdu = Vec3(std::cos(a), 0, -std::sin(a)) * 4.0f;
  h.p = {0, 0, -3};
  TextureCoords tc = fp.at(h);
  EXPECT_NEAR(tc.dudx, 2.0f / 64, 1e-5f);
  EXPECT_NEAR(tc.dvdy, 1.0f / 64, 1e-6f);
}
