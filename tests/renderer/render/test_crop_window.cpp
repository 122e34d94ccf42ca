// film.crop_window (pbrt-v4's crop window): the cropped render is the crop of the full render,
// bit for bit, whatever the sampler, sample count, reconstruction or adaptive refinement,
// because pixels keep their full-image coordinates for sampling and camera rays and the
// pixels that can reach the crop (splatting, adaptive neighbours) are rendered with it.
#include "renderer/scene/crop_window.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace pdrt;
using namespace pdrt::test;

namespace {

// 48 x 32, crop [0.55, 0.9] x [0.1, 0.45]: pixels 27..43 x 4..14, off the centre and
// across a tile border (x = 32).
constexpr std::array<float, 4> kCrop{0.55f, 0.9f, 0.1f, 0.45f};

SceneDesc crop_scene(const char* sampler, int spp) {
  SceneDesc s = base_scene(48, 32, spp);
  s.sampler.type = sampler;
  s.camera.position = {0, 1, 4}, s.camera.look_at = {0, 0, 0};
  s.camera.aperture_radius = 0.05f;
  s.environment.radiance = Vec3(0.3f);
  s.shapes.push_back(quad({-3, -1, -3}, {0, 0, 6}, {6, 0, 0}, add_material(s, diffuse(0.7f))));
  s.shapes.push_back(sphere({0, 0, 0}, 0.7f, add_material(s, diffuse(0.5f))));
  s.shapes.push_back(sphere({1, 2, 1}, 0.3f, add_material(s, emitter(5.0f))));
  s.film.filter.type = FilterType::Gaussian, s.film.filter.radius = 1.5f;
  return s;
}

// Every plane of `part` equals the rectangle r of `full`, bit for bit; returns the count of
// differing floats.
int64_t differences(const Image& full, const Image& part, PixelRect r) {
  EXPECT_EQ(part.width, r.width());
  EXPECT_EQ(part.height, r.height());
  if (part.width != r.width() || part.height != r.height()) return -1;
  int64_t bad = 0;
  auto plane = [&](const std::vector<float>& f, const std::vector<float>& p, int k) {
    for (int y = 0; y < r.height(); ++y)
      bad += std::memcmp(&f[k * (std::size_t(y + r.y0) * full.width + r.x0)], &p[k * std::size_t(y) * part.width],
                         k * std::size_t(r.width()) * sizeof(float)) != 0;
  };
  plane(full.rgb, part.rgb, 3), plane(full.samples, part.samples, 1), plane(full.variance, part.variance, 1);
  plane(full.albedo, part.albedo, 3), plane(full.normal, part.normal, 3), plane(full.depth, part.depth, 1);
  return bad;
}

void expect_crop_equals_full(SceneDesc s, const std::string& what) {
  Image full = render_quietly(s).image;
  s.film.crop_window = kCrop;
  Image part = render_quietly(s).image;
  EXPECT_EQ(differences(full, part, crop_pixels(kCrop, 48, 32)), 0) << what;
}

}  // namespace

// pbrt-v4's rule: pixels ceil(size lo) .. ceil(size hi) - 1.
TEST(CropWindow, PixelsAreTheCeilingsOfTheBounds) {
  PixelRect r = crop_pixels(kCrop, 48, 32);
  EXPECT_EQ(r.x0, 27);
  EXPECT_EQ(r.x1, 44);
  EXPECT_EQ(r.y0, 4);
  EXPECT_EQ(r.y1, 15);
  PixelRect all = crop_pixels({0, 1, 0, 1}, 48, 32);
  EXPECT_EQ(all.x0, 0);
  EXPECT_EQ(all.x1, 48);
  EXPECT_EQ(all.y0, 0);
  EXPECT_EQ(all.y1, 32);
  EXPECT_TRUE(crop_pixels({0.501f, 0.52f, 0, 1}, 48, 32).empty());  // ceil: 25 .. 25, no pixel
  EXPECT_EQ(crop_pixels({0.5f, 0.51f, 0, 1}, 48, 32).width(), 1);   // 24.0 .. 24.48: pixel 24
}

// pbrt-v4's pixelbounds as a window: every rectangle of a few film sizes maps back to itself.
TEST(CropWindow, PixelBoundsRoundTripThroughTheWindow) {
  for (int w : {1, 3, 10, 48, 1000, 4097})
    for (int a = 0; a <= w; a += std::max(1, w / 7))
      for (int b = a + 1; b <= w; b += std::max(1, w / 5)) {
        PixelRect r = crop_pixels(crop_window_for_pixels(a, b, a, b, w, w), w, w);
        ASSERT_EQ(r.x0, a) << w;
        ASSERT_EQ(r.x1, b) << w;
      }
}

TEST(CropWindow, CroppedRenderIsTheCropOfTheFullRender) {
  for (const char* sampler : {"poisson", "sobol", "jitter", "poisson-ss", "poisson-bn"})
    for (int spp : {1, 4})
      for (Reconstruction m : {Reconstruction::Importance, Reconstruction::Rank}) {
        SceneDesc s = crop_scene(sampler, spp);
        s.film.filter.reconstruction = m;
        expect_crop_equals_full(s, std::string(sampler) + " " + std::to_string(spp) + " spp " + reconstruction_name(m));
      }
}

// Splatting: samples of pixels outside the crop splat into it in the full render, so the
// cropped render traces the pixels within the filter's reach (ceil(radius) + 1) too, in the
// full render's tile waves; what splats from them past the rendered rectangle is dropped.
TEST(CropWindow, SplattedCroppedRenderIsTheCropOfTheFullRender) {
  for (const char* sampler : {"poisson", "sobol", "poisson-ss", "poisson-bn"})
    for (int spp : {1, 4}) {
      SceneDesc s = crop_scene(sampler, spp);
      s.film.filter.reconstruction = Reconstruction::Splat;
      expect_crop_equals_full(s, std::string(sampler) + " " + std::to_string(spp) + " spp");
    }
}

// Adaptive rounds: a pixel refines when a neighbour has not converged, so the crop renders
// with a margin of (log2(max_spp / min_spp) + 1) (reach + 1) + reach pixels, the distance a
// refinement can travel in that many rounds (docs/renderer.md: a longer cascade could cross
// it; these renders take 6 or 7 rounds, the margin covers 5, and still match: cascades are
// short). relative-error needs no image mean (error-per-sample's would be the crop's).
TEST(CropWindow, AdaptiveCroppedRenderIsTheCropOfTheFullRender) {
  for (const char* sampler : {"poisson", "sobol", "poisson-ss", "poisson-bn"})
    for (Reconstruction m : {Reconstruction::Importance, Reconstruction::Splat}) {
      SceneDesc s = crop_scene(sampler, 4);
      s.film.filter.reconstruction = m;
      s.sampler.adaptive.enabled = true;
      s.sampler.adaptive.metric = AdaptiveMetricKind::RelativeError;
      s.sampler.adaptive.threshold = 0.05f;
      s.sampler.adaptive.min_spp = 1, s.sampler.adaptive.max_spp = 16;
      RenderResult full = render_quietly(s);
      EXPECT_GT(full.stats.adaptive_rounds, 1);
      s.film.crop_window = kCrop;
      RenderResult part = render_quietly(s);
      EXPECT_EQ(differences(full.image, part.image, crop_pixels(kCrop, 48, 32)), 0)
          << sampler << " " << reconstruction_name(m);
      double samples = 0;
      for (float n : part.image.samples) samples += n;
      EXPECT_GT(samples, 17 * 11);  // some pixels refined
      EXPECT_DOUBLE_EQ(part.stats.spp_mean, samples / (17 * 11));
    }
}
