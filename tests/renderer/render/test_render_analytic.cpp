// Analytic renderer tests: each compares rendered pixels with a closed-form answer.
#include "renderer/render/embree_scene.h"
#include "renderer/render/filter.h"
#include "renderer/compare/image_metrics.h"
#include "renderer/render/light_set.h"
#include "renderer/render/path_integrator.h"
#include "tests/support/render_fixtures.h"
#include "renderer/render/thin_lens_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>

using namespace pdrt;
using namespace pdrt::test;

// A diffuse sphere of albedo a in a uniform white environment shows exactly a (furnace).
TEST(RenderAnalytic, FurnaceDiffuseSphereShowsItsAlbedo) {
  SceneDesc s = base_scene(48, 48, 64);
  s.camera.position = {0, 0, 4}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 30;
  s.environment.radiance = Vec3(1.0f);
  s.shapes.push_back(sphere({0, 0, 0}, 1, add_material(s, diffuse(0.5f))));
  Image im = render_quietly(s).image;
  ThinLensCamera cam(s.camera, 48, 48);
  double sum = 0, worst = 0;
  int n = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      // Pixels well inside the silhouette (radius ~ 0.5 of the projected radius).
      double dx = x + 0.5 - 24, dy = y + 0.5 - 24;
      auto edge = cam.project({0.5f, 0, 1});
      double rad = edge[0] - 24;
      if (dx * dx + dy * dy > rad * rad) continue;
      double v = mean_rgb(im, x, y);
      sum += v, ++n, worst = std::max(worst, std::abs(v - 0.5));
    }
  ASSERT_GT(n, 50);
  EXPECT_NEAR(sum / n, 0.5, 0.01) << "mean over " << n << " pixels";  // ±2 % of a
  EXPECT_LT(worst, 0.05) << "every pixel within ±10 % at 64 spp";
}

// The plane y = 0 of albedo rho seen from above at max_depth 1, with a quad facing down over
// [x0, x1] x [z0, z1] at height h (its material `quad_material`): 20 pixels match
// rho * expected(F) within ±3 % at 256 spp, F the quad's form factor from the pixel's centre.
namespace {

struct PlaneUnderQuad {
  float rho = 0.8f, x0 = -0.3f, x1 = 0.5f, z0 = -0.2f, z1 = 0.4f, h = 1.0f;
};

void expect_plane_under_quad(SceneDesc s, const PlaneUnderQuad& q, const Material& quad_material,
                             const std::function<double(double)>& expected) {
  const int W = s.film.width;
  s.camera.position = {0, 0.5f, 0}, s.camera.look_at = {0, 0, 0}, s.camera.up = {0, 0, -1};
  s.camera.vfov_deg = 90;  // sees [-0.5, 0.5]^2 of the plane y = 0
  s.shapes.push_back(quad({-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, add_material(s, diffuse(q.rho))));  // normal +y
  s.shapes.push_back(quad({q.x0, q.h, q.z0}, {q.x1 - q.x0, 0, 0}, {0, 0, q.z1 - q.z0}, add_material(s, quad_material)));
  s.integrator.max_depth = 1;  // direct light only
  Image im = render_quietly(s).image;
  ThinLensCamera cam(s.camera, W, W);
  int checked = 0;
  for (float px : {-0.35f, -0.1f, 0.0f, 0.2f, 0.4f})
    for (float pz : {-0.4f, -0.05f, 0.1f, 0.35f}) {
      auto f = cam.project({px, 0, pz});
      int x = int(f[0]), y = int(f[1]);
      // Pixel centre back on the plane (the footprint is small: irradiance is smooth).
      double cx = (x + 0.5) / W - 0.5, cz = (y + 0.5) / W - 0.5;
      auto g = cam.project({float(cx), 0, float(cz)});
      ASSERT_NEAR(g[0], x + 0.5, 1e-3);
      const double e = q.rho * expected(rect_form_factor(cx, cz, q.x0, q.x1, q.z0, q.z1, q.h));
      EXPECT_NEAR(mean_rgb(im, x, y), e, 0.03 * e) << "pixel " << x << "," << y;
      ++checked;
    }
  EXPECT_EQ(checked, 20);
}

}  // namespace

// A diffuse plane under a parallel quad light: radiance rho * Le * F(point -> light).
TEST(RenderAnalytic, DiffusePlaneMatchesQuadLightIrradiance) {
  const float Le = 2.0f;
  expect_plane_under_quad(base_scene(64, 64, 256), PlaneUnderQuad{}, emitter(Le), [&](double F) { return Le * F; });
}

// The same under a light much wider than the view: the light's area pdf is low, so MIS gives
// most of the weight to BSDF-sampled rays that hit the light at the path's last vertex.
TEST(RenderAnalytic, DiffusePlaneMatchesAWideLightReachedByBsdfSampling) {
  const float Le = 2.0f;
  PlaneUnderQuad q;
  q.x0 = -6, q.x1 = 5, q.z0 = -5, q.z1 = 6, q.h = 0.7f;
  expect_plane_under_quad(base_scene(64, 64, 256), q, emitter(Le), [&](double F) { return Le * F; });
}

// A uniform environment of radiance L and a black quad: radiance rho * L * (1 - F). With no
// emitter in the scene, the BSDF-sampled ray at the last vertex is an occlusion query
// (path_integrator.cpp): a ray the quad blocks must add nothing.
TEST(RenderAnalytic, DiffusePlaneSeesTheEnvironmentAnOccluderLeavesOpen) {
  const float L = 1.5f;
  SceneDesc s = base_scene(64, 64, 256);
  s.environment.radiance = Vec3(L);
  expect_plane_under_quad(s, PlaneUnderQuad{}, diffuse(0.0f), [&](double F) { return L * (1 - F); });
}

// Cook Fig. 13: a white square moving during the shutter leaves a streak whose value is
// the fraction of the shutter each pixel was covered.
TEST(RenderAnalytic, MovingSquareStreakEqualsCoveredShutterFraction) {
  const int W = 96, H = 64;
  SceneDesc s = base_scene(W, H, 64);
  s.camera.position = {0, 0, 10}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 20;
  ThinLensCamera cam(s.camera, W, H);
  // A 0.3-wide, 1-tall rectangle whose centre moves from x = -1.05 to x = +1.05 over the shutter.
  ShapeDesc q = quad({-0.15f, -0.5f, 0}, {0.3f, 0, 0}, {0, 1.0f, 0}, add_material(s, emitter(1.0f)));
  MotionKey k0, k1;
  k0.time = 0, k0.translate = {-1.05f, 0, 0};
  k1.time = 1, k1.translate = {1.05f, 0, 0};
  q.motion = {k0, k1};
  s.shapes.push_back(q);
  Image im = render_quietly(s).image;
  // In the middle of the streak a pixel is covered for side / distance of the shutter.
  const double expected = 0.3 / 2.1;
  auto a = cam.project({-0.5f, 0, 0}), b = cam.project({0.5f, 0, 0});
  auto top = cam.project({0, 0.35f, 0}), bottom = cam.project({0, -0.35f, 0});
  double sum = 0;
  int n = 0;
  for (int y = int(top[1]) + 1; y < int(bottom[1]); ++y)
    for (int x = int(a[0]) + 1; x < int(b[0]); ++x) sum += mean_rgb(im, x, y), ++n;
  ASSERT_GT(n, 100);
  EXPECT_NEAR(sum / n, expected, 0.03 * expected) << n << " pixels";  // ±3 %
}

namespace {

// Horizontal spread of a blurred point: sqrt of the variance of x weighted by brightness.
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

SceneDesc dof_scene(float point_depth) {
  SceneDesc s = base_scene(64, 64, 256);
  s.camera.position = {0, 0, 0}, s.camera.look_at = {0, 0, -1}, s.camera.vfov_deg = 20;
  s.camera.aperture_radius = 0.1f, s.camera.focus_distance = 5;
  s.shapes.push_back(sphere({0, 0, -point_depth}, 0.01f, add_material(s, emitter(1.0f))));
  return s;
}

}  // namespace

// A point at the focus distance stays sharp: its image (a disk of radius 0.36 px centred on
// the corner of pixels 31 and 32 in x and y) reaches only those two columns under the box
// filter, so no light falls elsewhere, and the horizontal spread is at most that of two
// columns (sqrt(w31 w32) <= 0.5; it is 0.5 when the halves are equal, as symmetry makes them).
TEST(RenderAnalytic, PointAtFocusDistanceStaysSharp) {
  Image im = render_quietly(dof_scene(5)).image;
  double cx, sd = spread_x(im, &cx);
  EXPECT_NEAR(cx, 32, 0.1);
  EXPECT_LE(sd, 0.5 + 1e-6);
  double inside = 0, total = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const double v = mean_rgb(im, x, y);
      total += v;
      if ((x == 31 || x == 32) && (y == 31 || y == 32)) inside += v;
    }
  EXPECT_GT(total, 0);
  EXPECT_EQ(inside, total) << "light outside the four pixels around the point";
}

// Off focus the point spreads over the thin-lens circle of confusion: diameter on the plane
// of focus 2A|d - f|/d, i.e. radius A|d - f| H / (2 d f tan(fov/2)) pixels; a uniform disk of
// radius R has a horizontal standard deviation of R/2.
TEST(RenderAnalytic, OffFocusPointSpreadsOverCircleOfConfusion) {
  const float d = 2.5f, f = 5, A = 0.1f, H = 64;
  Image im = render_quietly(dof_scene(d)).image;
  double cx, sd = spread_x(im, &cx);
  double R = A * std::abs(d - f) * H / (2 * d * f * std::tan(10 * M_PI / 180));
  double point_sd = 0.01 * f / d * H / (2 * f * std::tan(10 * M_PI / 180)) / 2;  // the sphere's own size
  double expected = std::sqrt(R * R / 4 + point_sd * point_sd + 1.0 / 12);       // + the pixel's box
  EXPECT_NEAR(cx, 32, 0.2);
  EXPECT_NEAR(sd, expected, 0.05 * expected) << "R = " << R << " px";
}

TEST(RenderDeterminism, ImageIsBitIdenticalAtOneAndTwoThreads) {
  SceneDesc s = base_scene(40, 24, 8);
  s.camera.position = {0, 1, 4}, s.camera.look_at = {0, 0, 0};
  s.camera.aperture_radius = 0.05f;
  s.environment.radiance = Vec3(0.3f);
  s.shapes.push_back(quad({-3, -1, -3}, {0, 0, 6}, {6, 0, 0}, add_material(s, diffuse(0.7f))));
  s.shapes.push_back(sphere({0, 0, 0}, 0.7f, add_material(s, diffuse(0.5f))));
  s.shapes.push_back(sphere({1, 2, 1}, 0.3f, add_material(s, emitter(5.0f))));
  s.film.filter.type = FilterType::Gaussian, s.film.filter.radius = 1.5f;
  for (const char* sampler : {"poisson", "jitter", "sobol", "random", "poisson-ss", "poisson-bn"}) {
    s.sampler.type = sampler;
    Image a = render_quietly(s, 1).image, b = render_quietly(s, 2).image;
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    EXPECT_EQ(0, std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float))) << sampler;
    EXPECT_EQ(0, std::memcmp(a.variance.data(), b.variance.data(), a.variance.size() * sizeof(float))) << sampler;
  }
}

TEST(Filter, WeightsVanishPastTheRadius) {
  for (FilterType t : {FilterType::Box, FilterType::Tent, FilterType::Gaussian, FilterType::Mitchell}) {
    for (float r : {0.5f, 1.0f, 1.5f, 2.0f}) {
      FilterDesc d;
      d.type = t, d.radius = r;
      Filter f(d);
      EXPECT_GT(f.eval(0, 0), 0);
      for (int i = 0; i < 64; ++i) {
        float a = 2 * kPi * i / 64;
        EXPECT_EQ(f.eval(r * std::cos(a) * 1.0001f + (std::cos(a) >= 0 ? 1e-6f : -1e-6f), r * 1.0001f), 0.0f);
        EXPECT_EQ(f.eval(r * 1.0001f, r * std::sin(a)), 0.0f);
      }
      if (t == FilterType::Gaussian) {  // Cook's e^-d^2 - e^-w^2 reaches 0 at d = w
        EXPECT_NEAR(f.eval(r * 0.9999f, 0), 0.0f, 1e-3f);
      }
    }
  }
}

// The same pixel and sample index replay the same path, bit for bit.
TEST(RenderDeterminism, SamePixelAndSampleIndexReplayTheSamePath) {
  SceneDesc s = base_scene(16, 16, 1);
  s.camera.position = {0, 1, 4}, s.camera.look_at = {0, 0, 0};
  s.environment.radiance = Vec3(0.5f);
  s.shapes.push_back(quad({-3, -1, -3}, {0, 0, 6}, {6, 0, 0}, add_material(s, diffuse(0.7f))));
  s.shapes.push_back(sphere({0, 0, 0}, 0.7f, add_material(s, diffuse(0.5f))));
  EmbreeDevice device;
  EmbreeScene scene(s, device);
  MaterialSet materials(scene, TextureFootprint(s.camera, 16, 16, s.sampler.spp), s.integrator.regularize);
  LightSet lights(scene, materials.textures());
  PathIntegrator integrator(scene, lights, materials, s.integrator);
  ThinLensCamera cam(s.camera, 16, 16);
  auto sampler = make_scene_sampler(s.sampler, s.film);
  PixelSampleState a(*sampler), b(*sampler);
  int differing = 0;
  for (int i = 0; i < 64; ++i) {
    a.start_pixel_sample(7, 9, i);
    b.start_pixel_sample(3, 3, 5);  // disturb b's state in between
    b.start_pixel_sample(7, 9, i);
    Ray ray = cam.generate(7.5f, 9.5f, a.get_2d(Family::Lens), 0);
    PathResult ra = integrator.trace(ray, a), rb = integrator.trace(ray, b);
    ASSERT_EQ(0, std::memcmp(&ra.radiance, &rb.radiance, sizeof(Vec3)));
    ASSERT_EQ(ra.rays, rb.rays);
    if (i > 0) {
      a.start_pixel_sample(7, 9, i - 1);
      differing += integrator.trace(ray, a).radiance.x != ra.radiance.x;
    }
  }
  EXPECT_GT(differing, 32) << "different sample indices must give different paths";
}

// Filter importance by rank threshold (McCool–Fiume §5.2): the kept samples have density
// proportional to the filter, so the image matches importance reconstruction while tracing
// the same number of samples on average (spp / mean_keep candidates, each kept with
// probability x).
TEST(RenderAnalytic, RankSelectedFilterMatchesImportanceAtEqualSamples) {
  SceneDesc s = base_scene(32, 32, 64);
  s.camera.position = {0, 0, 4}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 30;
  s.environment.radiance = Vec3(1.0f);
  s.shapes.push_back(sphere({0, 0, 0}, 1, add_material(s, diffuse(0.5f))));
  s.film.filter.type = FilterType::Gaussian, s.film.filter.radius = 1.5f;
  RenderResult w = render_quietly(s);
  s.film.filter.reconstruction = Reconstruction::Rank;
  RenderResult r = render_quietly(s);
  EXPECT_EQ(w.stats.samples, 32 * 32 * 64);
  EXPECT_NEAR(double(r.stats.samples) / (32 * 32 * 64), 1.0, 0.03) << "fraction of the asked samples traced";
  double sw = 0, sr = 0;
  int n = 0;
  for (int y = 12; y < 20; ++y)
    for (int x = 12; x < 20; ++x) sw += mean_rgb(w.image, x, y), sr += mean_rgb(r.image, x, y), ++n;
  EXPECT_NEAR(sr / n, 0.5, 0.01);
  EXPECT_NEAR(sw / n, 0.5, 0.01);
}

// A white glossy sphere in a white furnace never shows more than 1 (GGX and Phong lobes).
TEST(RenderAnalytic, FurnaceGlossyLobeNeverCreatesEnergy) {
  for (bool phong : {false, true}) {
    SceneDesc s = base_scene(32, 32, 64);
    s.camera.position = {0, 0, 4}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 30;
    s.environment.radiance = Vec3(1.0f);
    Material m;
    m.type = MaterialType::Glossy, m.albedo = Vec3(1.0f);
    if (phong)
      m.lobe = GlossLobe::Phong, m.exponent = 20;
    else
      m.roughness = 0.5f;
    s.shapes.push_back(sphere({0, 0, 0}, 1, add_material(s, m)));
    Image im = render_quietly(s).image;
    double sum = 0;
    int n = 0;
    for (int y = 10; y < 22; ++y)
      for (int x = 10; x < 22; ++x) sum += mean_rgb(im, x, y), ++n;
    EXPECT_LE(sum / n, 1.0 + 0.01) << (phong ? "phong" : "ggx");  // mean over 144 pixels x 64 spp
    EXPECT_GT(sum / n, 0.8) << (phong ? "phong" : "ggx");
  }
}

// Stratified samplers must converge to the same image as independent random sampling: sample
// i of the pixel, light and gloss families must not be tied to each other by a fixed map
// (shuffle_index). Before the fix jitter and Sobol stalled at 4x random's error here.
TEST(RenderDeterminism, StratifiedSamplersConvergeToTheRandomSamplerImage) {
  auto scene = [](const char* sampler, int spp, uint64_t seed) {
    SceneDesc s = base_scene(24, 16, spp);
    s.camera.position = {0, 3, 6}, s.camera.look_at = {0, 0.5f, 0};
    s.integrator.max_depth = 1;
    s.shapes.push_back(quad({-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, add_material(s, diffuse(0.7f))));
    s.shapes.push_back(sphere({0, 0.7f, 0}, 0.7f, add_material(s, diffuse(0.6f))));
    s.shapes.push_back(quad({-1.5f, 4, 1.5f}, {0, 0, -3}, {3, 0, 0}, add_material(s, emitter(5.0f))));
    s.sampler.type = sampler, s.sampler.seed = seed;
    return render_quietly(s).image;
  };
  Image truth = scene("random", 8192, 1);
  double random_err = rmse(scene("random", 512, 2), truth);
  for (const char* s : {"jitter", "sobol", "poisson"})
    EXPECT_LT(rmse(scene(s, 512, 3), truth), 1.3 * random_err) << s << " vs random " << random_err;
}
