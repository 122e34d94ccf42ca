// Rendering with `poisson-ip` (issue 31 item 2): every pixel traces its count of the image-plane
// pattern over the progressive passes, the splat divided by the expected weight is unbiased over
// seeds at every pixel (the image's border included), images are bit-identical at any thread
// count and under a crop window, and the settings it cannot serve are refused.
#include "renderer/render/expected_splat_weight.h"
#include "renderer/scene/render_settings.h"
#include "sampling/core/errors.h"
#include "tests/support/filter_quadrature.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace pdrt {
namespace {
using namespace test;

// A bright half-plane seen head-on, its edge on the film's column boundary x = 16 of a 32 x 16
// film (as in test_reconstruction.cpp), splatted with the Gaussian of radius 1.5.
SceneDesc edge_scene(int spp, uint64_t seed) {
  SceneDesc s = base_scene(32, 16, spp);
  s.camera.position = {1000, 0, 5}, s.camera.look_at = {1000, 0, 0};
  s.shapes.push_back(quad({900, -100, 0}, {100, 0, 0}, {0, 200, 0}, add_material(s, emitter(1.0f))));
  s.film.filter.type = FilterType::Gaussian, s.film.filter.radius = 1.5f;
  s.film.filter.reconstruction = Reconstruction::Splat;
  s.sampler.type = "poisson-ip";
  s.sampler.seed = seed;
  return s;
}

// Pixel (x, y)'s filter over the part of the W x H image left of column `edge`, divided by its
// filter over the whole image: what a splat converges to, the border pixels' filters cut.
double filtered_edge(const Filter& f, int x, int y, int W, int H, double edge) {
  auto in = [&](double dx, double dy) {
    const double px = x + 0.5 + dx, py = y + 0.5 + dy;
    return px >= 0 && px < W && py >= 0 && py < H;
  };
  const double lit = filter_quadrature(
      f, [&](double dx, double dy, double v) { return in(dx, dy) && x + 0.5 + dx < edge ? v : 0.0; }, 600);
  const double all = filter_quadrature(
      f, [&](double dx, double dy, double v) { return in(dx, dy) ? v : 0.0; }, 600);
  return lit / all;
}

TEST(ImagePlaneRender, SplatOverExpectedWeightIsUnbiasedOverSeedsAtEveryPixel) {
  // 64 seeds at 4 spp: every pixel's mean within 5 standard errors of the filtered edge (the
  // left border, the corners, the top and bottom rows and the edge's columns included), and
  // every column's mean over rows within 4 of theirs.
  const int W = 32, H = 16, seeds = 64;
  std::vector<double> sum(W * H, 0.0), sum2(W * H, 0.0);
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    const Image im = render_quietly(edge_scene(4, seed)).image;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const double v = mean_rgb(im, x, y);
        sum[y * W + x] += v, sum2[y * W + x] += v * v;
      }
  }
  const Filter f(edge_scene(4, 1).film.filter);
  for (int x = 0; x < W; ++x) {
    double col = 0, col_var = 0;
    for (int y = 0; y < H; ++y) {
      const double mean = sum[y * W + x] / seeds, var = std::max(0.0, sum2[y * W + x] / seeds - mean * mean);
      const double exact = filtered_edge(f, x, y, W, H, 16);
      EXPECT_NEAR(mean, exact, 5 * std::sqrt(var / seeds) + 1e-4) << x << "," << y;
      col += mean - exact, col_var += var / seeds;
    }
    EXPECT_NEAR(col / H, 0.0, 4 * std::sqrt(col_var) / H + 1e-5) << "column " << x;
  }
}

TEST(ImagePlaneRender, ExpectedWeightIsTheFiltersIntegralCutAtTheImage) {
  FilterDesc d;
  d.type = FilterType::Gaussian, d.radius = 1.5f;
  const Filter f(d);
  const ExpectedSplatWeight e(f, 10, 6);
  const double whole = filter_quadrature(
      f, [](double, double, double v) { return v; }, 1200);
  EXPECT_NEAR(e.at(5, 3), whole, 1e-4 * whole);
  const double corner = filter_quadrature(
      f, [](double dx, double dy, double v) { return dx >= -0.5 && dy >= -0.5 ? v : 0.0; }, 1200);
  EXPECT_NEAR(e.at(0, 0), corner, 1e-4 * whole);
  EXPECT_LT(e.at(0, 0), 0.7 * whole);  // the corner pixel misses a third of its filter
}

TEST(ImagePlaneRender, EveryPixelTracesItsCountOfThePatternOverThePasses) {
  // 16 spp in passes of 8 and 16: the samples plane holds each pixel's traced count, which is
  // the sampler's samples_in_pixel(16), not 16 (counts vary about it), and averages 16.
  SceneDesc s = edge_scene(16, 3);
  auto sampler = make_scene_sampler(s.sampler, s.film);
  const RenderResult r = render_quietly(s);
  int differ = 0;
  double total = 0;
  for (int y = 0; y < s.film.height; ++y)
    for (int x = 0; x < s.film.width; ++x) {
      const float traced = r.image.samples[std::size_t(y) * s.film.width + x];
      ASSERT_EQ(traced, float(sampler->samples_in_pixel(x, y, 16))) << x << "," << y;
      differ += traced != 16.0f, total += traced;
    }
  EXPECT_GT(differ, 0);
  EXPECT_NEAR(total / (s.film.width * s.film.height), 16.0, 0.5);
}

TEST(ImagePlaneRender, ImageIsBitIdenticalAtOneAndTwoThreadsAndUnderACropWindow) {
  SceneDesc s = edge_scene(4, 11);
  s.camera.aperture_radius = 0.5f, s.camera.focus_distance = 3;  // lens samples too
  const Image a = render_quietly(s, 1).image, b = render_quietly(s, 2).image;
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  EXPECT_EQ(0, std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)));
  s.film.crop_window = {0.25f, 0.75f, 0.25f, 1.0f};
  const Image c = render_quietly(s, 2).image;
  ASSERT_EQ(c.width, 16);
  ASSERT_EQ(c.height, 12);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(c.rgb[3 * (std::size_t(y) * c.width + x) + k], a.rgb[3 * (std::size_t(y + 4) * a.width + x + 8) + k])
            << x << "," << y;
}

std::string problem(const SceneDesc& s) {
  const auto p = render_settings_problem(s);
  return p ? p->message : "";
}

TEST(ImagePlaneRender, SettingsItCannotServeAreRefused) {
  SceneDesc s = edge_scene(4, 1);
  EXPECT_EQ(problem(s), "");
  s.film.filter.reconstruction = Reconstruction::Importance;
  EXPECT_EQ(problem(s),
            "sampler \"poisson-ip\" needs reconstruction \"splat\" (its pixels take varying counts of one image-plane "
            "pattern's samples), got \"importance\"");
  s.film.filter.reconstruction = Reconstruction::Rank;
  EXPECT_NE(problem(s).find("got \"rank\""), std::string::npos);
  s.film.filter.reconstruction = Reconstruction::Splat;
  s.sampler.adaptive.enabled = true;
  EXPECT_EQ(problem(s),
            "sampler \"poisson-ip\" cannot refine adaptively (its pixels' samples are one image-plane pattern's, whose "
            "counts a pixel cannot raise alone)");
  s.sampler.adaptive.enabled = false, s.sampler.spp = 65537;
  EXPECT_EQ(problem(s),
            "sampler \"poisson-ip\" takes at most 65536 spp (the points of its image-plane pattern), got 65537");
  s.sampler.type_where = "s.json:7:14: sampler.type";
  try {
    check_render_settings(s);
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("s.json:7:14: sampler.type: sampler \"poisson-ip\" takes", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace pdrt
