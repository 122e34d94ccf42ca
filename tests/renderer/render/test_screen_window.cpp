// camera.screen_window (pbrt-v4's screen window): the default is the one vfov_deg or
// ortho_height gives, and an off-centre window shifts the image by whole pixels.
#include "renderer/render/screen_window.h"
#include "renderer/render/thin_lens_camera.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace pdrt;
using namespace pdrt::test;

namespace {

SceneDesc lit_scene(CameraDesc::Projection proj) {
  SceneDesc s = base_scene(48, 32, 4);
  s.camera.projection = proj;
  s.camera.position = {0.5f, 1, 4}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 35;
  s.camera.ortho_height = 3;
  s.camera.aperture_radius = 0.05f;
  s.film.filter.type = FilterType::Gaussian, s.film.filter.radius = 1.5f;
  s.environment.radiance = Vec3(0.3f);
  s.shapes.push_back(quad({-3, -1, -3}, {0, 0, 6}, {6, 0, 0}, add_material(s, diffuse(0.7f))));
  s.shapes.push_back(sphere({0.3f, 0, 0}, 0.7f, add_material(s, diffuse(0.5f))));
  s.shapes.push_back(sphere({1, 2, 1}, 0.3f, add_material(s, emitter(5.0f))));
  return s;
}

// Brightness-weighted centre of the image.
std::array<double, 2> centroid(const Image& im) {
  double w = 0, sx = 0, sy = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const double v = mean_rgb(im, x, y);
      w += v, sx += v * (x + 0.5), sy += v * (y + 0.5);
    }
  return {sx / w, sy / w};
}

}  // namespace

// The window written out as vfov_deg / ortho_height and the aspect give it (tan of half the
// field of view, or half the height, times width / height) renders the same image, bit for bit.
TEST(ScreenWindow, ExplicitDefaultWindowRendersTheSameImage) {
  for (auto proj : {CameraDesc::Projection::Perspective, CameraDesc::Projection::Orthographic}) {
    SceneDesc s = lit_scene(proj);
    const float aspect = 48.0f / 32.0f;
    const float half = proj == CameraDesc::Projection::Orthographic ? 1.5f : std::tan(0.5f * 35.0f * kPi / 180.0f);
    SceneDesc t = s;
    t.camera.has_screen_window = true;
    t.camera.screen_window = {-half * aspect, half * aspect, -half, half};
    t.camera.vfov_deg = 90, t.camera.ortho_height = 7;  // ignored under an explicit window
    Image a = render_quietly(s).image, b = render_quietly(t).image;
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    EXPECT_EQ(0, std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float))) << int(proj);
  }
}

// Moving the window by 5 pixel widths right and 3 pixel heights down (an off-axis frustum)
// moves a small emitter's image 5 pixels left and 3 up, for either projection; the
// projection agrees. Emitter: a sphere of radius 6-7 pixels well inside the image, on black;
// tolerance 0.03 px for the shift (sampling noise on the rim), 0.1 px for centroid vs projected
// centre (a perspective sphere images to an ellipse whose centroid is slightly outward).
TEST(ScreenWindow, OffCentreWindowShiftsTheImageByWholePixels) {
  for (auto proj : {CameraDesc::Projection::Perspective, CameraDesc::Projection::Orthographic}) {
    SceneDesc s = base_scene(64, 48, 16);
    s.camera.projection = proj;
    s.camera.position = {0, 0, 5}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 30, s.camera.ortho_height = 3;
    s.shapes.push_back(sphere({0.2f, -0.1f, 0}, 0.4f, add_material(s, emitter(1.0f))));
    const std::array<float, 4> w = screen_window(s.camera, 64, 48);
    const float px = (w[1] - w[0]) / 64, py = (w[3] - w[2]) / 48;
    SceneDesc t = s;
    t.camera.has_screen_window = true;
    t.camera.screen_window = {w[0] + 5 * px, w[1] + 5 * px, w[2] - 3 * py, w[3] - 3 * py};
    auto a = centroid(render_quietly(s).image), b = centroid(render_quietly(t).image);
    EXPECT_NEAR(b[0] - a[0], -5, 0.03) << int(proj);
    EXPECT_NEAR(b[1] - a[1], -3, 0.03) << int(proj);
    auto pa = ThinLensCamera(s.camera, 64, 48).project({0.2f, -0.1f, 0});
    auto pb = ThinLensCamera(t.camera, 64, 48).project({0.2f, -0.1f, 0});
    EXPECT_NEAR(pb[0] - pa[0], -5, 1e-3);
    EXPECT_NEAR(pb[1] - pa[1], -3, 1e-3);
    EXPECT_NEAR(a[0], pa[0], 0.1);
    EXPECT_NEAR(a[1], pa[1], 0.1);
  }
}
