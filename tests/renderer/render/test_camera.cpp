// Thin-lens camera: aperture sampling and projection.
#include "renderer/render/thin_lens_camera.h"

#include "sampling/analysis/incomplete_gamma.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;

namespace {

// Is (x, y) inside the regular `blades`-gon inscribed in the unit circle, rotated by `rot`?
bool inside_polygon(float x, float y, int blades, float rot) {
  for (int k = 0; k < blades; ++k) {
    float a0 = rot + 2 * kPi * k / blades, a1 = rot + 2 * kPi * (k + 1) / blades;
    float ex = std::cos(a1) - std::cos(a0), ey = std::sin(a1) - std::sin(a0);
    if (ex * (y - std::sin(a0)) - ey * (x - std::cos(a0)) < -1e-5f) return false;
  }
  return true;
}

}  // namespace

TEST(Camera, PolygonalAperturePointsStayInsideThePolygon) {
  Rng rng(3);
  for (int blades : {3, 5, 6, 8})
    for (int i = 0; i < 20000; ++i) {
      auto p = ThinLensCamera::aperture_point({rng.uniform(), rng.uniform()}, blades, 0.3f);
      ASSERT_TRUE(inside_polygon(p[0], p[1], blades, 0.3f)) << blades << " blades: " << p[0] << "," << p[1];
    }
}

// Uniform by area: counts in 8 equal-area rings x 16 sectors of the disk pass chi-square.
TEST(Camera, CircularApertureIsUniformByArea) {
  Rng rng(5);
  const int rings = 8, sectors = 16, n = 128000;
  std::vector<double> counts(rings * sectors, 0.0);
  for (int i = 0; i < n; ++i) {
    auto p = ThinLensCamera::aperture_point({rng.uniform(), rng.uniform()}, 0, 0);
    double r2 = p[0] * p[0] + p[1] * p[1];
    ASSERT_LE(r2, 1.0 + 1e-6);
    int ring = std::min(rings - 1, int(r2 * rings));
    double a = std::atan2(p[1], p[0]) + M_PI;
    int sec = std::min(sectors - 1, int(a / (2 * M_PI) * sectors));
    counts[ring * sectors + sec] += 1;
  }
  double expected = double(n) / (rings * sectors), chi2 = 0;
  for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
  EXPECT_GT(chi_square_p_value(chi2, rings * sectors - 1), 1e-3) << "chi2 = " << chi2;
}

TEST(Camera, PinholeRayThroughProjectedPointHitsIt) {
  CameraDesc d;
  d.position = {1, 2, 3}, d.look_at = {0, 0.5f, -1}, d.vfov_deg = 50;
  ThinLensCamera cam(d, 200, 100);
  Vec3 w(0.3f, 0.2f, -2);
  auto f = cam.project(w);
  Ray r = cam.generate(f[0], f[1], {0.5, 0.5}, 0);
  Vec3 to = normalize(w - r.org);
  EXPECT_NEAR(dot(to, r.dir), 1.0f, 1e-6f);
}
