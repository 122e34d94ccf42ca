// Motion keys that do not span the shutter: the motion is clamped outside its keys (as
// docs/scene-format.md says), so an object exists for the whole shutter, wherever its keys lie.
#include "renderer/render/thin_lens_camera.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

using namespace pdrt;
using namespace pdrt::test;

namespace {

double image_mean(const Image& im) {
  double sum = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) sum += mean_rgb(im, x, y);
  return sum / (double(im.width) * im.height);
}

MotionKey key_at(float time, Vec3 translate = Vec3(0.0f)) {
  MotionKey k;
  k.time = time, k.translate = translate;
  return k;
}

// A camera looking at a large two-sided emitter quad (radiance 1) that fills the view, placed
// `offset` away from the origin so no test sits at the comfortable spot.
SceneDesc filled_view(int spp, const std::string& sampler, Vec3 offset, float open, float close) {
  SceneDesc s = base_scene(8, 8, spp);
  s.sampler.type = sampler;
  s.camera.position = offset + Vec3(0, 0, 10), s.camera.look_at = offset, s.camera.vfov_deg = 10;
  s.camera.shutter_open = open, s.camera.shutter_close = close;
  s.shapes.push_back(quad(offset + Vec3(-5, -5, 0), {10, 0, 0}, {0, 10, 0}, add_material(s, emitter(1.0f, true))));
  return s;
}

}  // namespace

// A static emitter with identity keys inside the shutter is there for the whole shutter:
// every pixel reads exactly its radiance, at 1, 2 and 4 spp and with every sampler.
TEST(MotionKeys, IdentityKeysInsideTheShutterKeepTheObjectForTheWholeShutter) {
  struct Keys {
    float open, close;
    std::vector<float> times;
  };
  const std::vector<Keys> cases = {{0, 1, {0.5f, 1.0f}},           // second half, even
                                   {0, 1, {0.0f, 0.5f}},           // first half, even
                                   {0, 1, {0.3f, 0.4f, 0.9f}},     // uneven keys
                                   {2, 4, {2.5f, 3.0f, 3.5f}},     // a shutter away from 0
                                   {-1e3f, 1e3f, {-1.0f, 1.0f}}};  // keys far inside a long shutter
  for (const char* sampler : {"random", "jitter", "poisson", "poisson-065", "sobol"})
    for (int spp : {1, 2, 4})
      for (const Keys& c : cases) {
        SceneDesc s = filled_view(spp, sampler, {1e3f, -20, 3}, c.open, c.close);
        for (float t : c.times) s.shapes[0].motion.push_back(key_at(t));
        Image im = render_quietly(s).image;
        EXPECT_NEAR(image_mean(im), 1.0, 1e-5) << sampler << " spp " << spp << " keys from " << c.times.front();
      }
}

// A square that moves during the first half of the shutter and then rests: mid-streak pixels
// are covered for half of side/distance, and where it rests for the time since it arrived.
TEST(MotionKeys, SquareKeyedOverHalfTheShutterRestsAtItsLastKey) {
  const int W = 96, H = 64;
  SceneDesc s = base_scene(W, H, 64);
  s.camera.position = {0, 0, 10}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 20;
  ThinLensCamera cam(s.camera, W, H);
  ShapeDesc q = quad({-0.15f, -0.5f, 0}, {0.3f, 0, 0}, {0, 1.0f, 0}, add_material(s, emitter(1.0f)));
  q.motion = {key_at(0.0f, {-1.05f, 0, 0}), key_at(0.5f, {1.05f, 0, 0})};
  s.shapes.push_back(q);
  Image im = render_quietly(s).image;
  // World x of a pixel centre on the z = 0 plane (affine in the pixel's x there).
  auto a = cam.project({-0.5f, 0, 0}), b = cam.project({0.5f, 0, 0});
  auto world_x = [&](int px) { return -0.5 + (px + 0.5 - a[0]) / (b[0] - a[0]); };
  auto top = cam.project({0, 0.35f, 0}), bottom = cam.project({0, -0.35f, 0});
  double streak = 0, rest = 0, rest_expected = 0;
  int ns = 0, nr = 0;
  for (int y = int(top[1]) + 1; y < int(bottom[1]); ++y)
    for (int x = 0; x < W; ++x) {
      const double wx = world_x(x), half_pixel = 0.5 / (b[0] - a[0]);
      if (wx - half_pixel > -0.5 && wx + half_pixel < 0.5) streak += mean_rgb(im, x, y), ++ns;
      // Resting square [0.9, 1.2]: a point x there is covered from the time the moving left
      // edge reaches it, t = 0.5 (x - 0.15 + 1.05) / 2.1, to the end (linear in x, so the
      // box-filtered pixel reads the value at its centre).
      if (wx - half_pixel > 0.95 && wx + half_pixel < 1.15) {
        rest += mean_rgb(im, x, y), ++nr;
        rest_expected += 1.0 - 0.5 * (wx + 0.9) / 2.1;
      }
    }
  ASSERT_GT(ns, 100);
  ASSERT_GT(nr, 20);
  EXPECT_NEAR(streak / ns, 0.5 * 0.3 / 2.1, 0.03 * 0.5 * 0.3 / 2.1) << ns << " pixels";  // ±3 %
  EXPECT_NEAR(rest / nr, rest_expected / nr, 0.02 * rest_expected / nr) << nr << " pixels";
}

// A light keyed over part of the shutter is seen by camera rays for the whole shutter, as it
// lights the scene for the whole shutter (next-event estimation clamps the same way).
TEST(MotionKeys, EmitterKeyedOverPartOfTheShutterIsSeenByCameraRaysThroughout) {
  SceneDesc s = filled_view(4, "poisson", {-30, 5e2f, 0}, 0, 1);
  s.shapes[0].motion = {key_at(0.6f), key_at(0.8f, {0, 0, 0})};
  EXPECT_NEAR(image_mean(render_quietly(s).image), 1.0, 1e-5);
}
