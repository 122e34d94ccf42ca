// pbrt-v4's equal-area octahedral environment layout (renderer/scene/pbrt/
// equal_area_octahedral.h): the map's landmarks, its inverse, equal area (a uniform grid on
// the square is uniform on the sphere), and the resampling into pdrt's equirectangular image.
#include "renderer/scene/pbrt/equal_area_octahedral.h"

#include "renderer/scene/equirect.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;

namespace {
void expect_dir(const Vec3& a, const Vec3& b, const char* what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6) << what << " component " << c;
}
}  // namespace

TEST(EqualAreaOctahedral, LandmarksSitWherePbrtPutsThem) {
  expect_dir(equal_area_square_to_sphere(0.5, 0.5), {0, 0, 1}, "centre");
  for (double u : {0.0, 1.0})
    for (double v : {0.0, 1.0}) expect_dir(equal_area_square_to_sphere(u, v), {0, 0, -1}, "corner");
  expect_dir(equal_area_square_to_sphere(1, 0.5), {1, 0, 0}, "right edge midpoint");
  expect_dir(equal_area_square_to_sphere(0, 0.5), {-1, 0, 0}, "left edge midpoint");
  expect_dir(equal_area_square_to_sphere(0.5, 1), {0, 1, 0}, "bottom edge midpoint");
  expect_dir(equal_area_square_to_sphere(0.5, 0), {0, -1, 0}, "top edge midpoint");
}

TEST(EqualAreaOctahedral, SphereToSquareInvertsSquareToSphere) {
  pdrt::Rng rng(7);
  for (int i = 0; i < 20000; ++i) {
    const double u = rng.uniform(), v = rng.uniform();
    const Vec3 d = equal_area_square_to_sphere(u, v);
    ASSERT_NEAR(length(d), 1, 1e-6);
    const auto st = equal_area_sphere_to_square(d);
    const Vec3 back = equal_area_square_to_sphere(st[0], st[1]);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(back[c], d[c], 2e-6) << "u " << u << " v " << v;
  }
}

TEST(EqualAreaOctahedral, EqualAreasOfTheSquareAreEqualSolidAngles) {
  // Texel centres of a 256^2 grid: the fraction inside a cap of half-angle a about any axis is
  // the cap's solid-angle fraction (1 - cos a) / 2, to within the texels its rim cuts.
  const int n = 256;
  const Vec3 axes[] = {{0, 0, 1}, {0, 0, -1}, normalize(Vec3(1, 2, -0.5f)), normalize(Vec3(-1, 0.1f, 0.3f))};
  for (const Vec3& axis : axes)
    for (double a : {0.3, 1.0, 2.0}) {
      int inside = 0;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          inside += dot(equal_area_square_to_sphere((x + 0.5) / n, (y + 0.5) / n), axis) > std::cos(a);
      const double expect = (1 - std::cos(a)) / 2;
      EXPECT_NEAR(double(inside) / (n * n), expect, 3e-3)
          << "cap " << a << " about " << axis.x << " " << axis.y << " " << axis.z;
    }
}

TEST(EqualAreaOctahedral, ResamplingGivesTheSameRadianceInTheSameDirection) {
  // A smooth function of direction written in pbrt's layout reads back through pdrt's
  // equirectangular parameterisation, rotated by the light's transform.
  const int n = 64;
  auto radiance = [](const Vec3& w) { return Vec3(1 + w.x, 1 + w.y, 1 + w.z); };
  EnvironmentImage src;
  src.width = src.height = n;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Vec3 r = radiance(equal_area_square_to_sphere((x + 0.5) / n, (y + 0.5) / n));
      src.rgb.insert(src.rgb.end(), {r.x, r.y, r.z});
    }
  // pbrt scenes turn +z up with Rotate -90 1 0 0: light space (x, y, z) is world (x, z, -y).
  auto to_light = [](const Vec3& w) { return Vec3(w.x, -w.z, w.y); };
  EnvironmentImage eq = octahedral_to_equirect(src, to_light);
  ASSERT_EQ(eq.width, 2 * n);
  ASSERT_EQ(eq.height, n);
  double worst = 0;
  for (int j = 0; j < eq.height; ++j)
    for (int i = 0; i < eq.width; ++i) {
      const Vec3 w = equirect_direction((i + 0.5) / eq.width, (j + 0.5) / eq.height);
      const Vec3 expect = radiance(to_light(w));
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(eq.rgb[3 * (j * eq.width + i) + c]) - expect[c]));
    }
  // A linear function is reproduced up to the texel size (2 / 64) and the fold at the edges.
  EXPECT_LT(worst, 0.05);
  // The zenith row (world +y) reads light-space +z: blue channel 2.
  EXPECT_NEAR(eq.rgb[3 * (0 * eq.width + n) + 2], 2, 0.03);
}
