// Emitters whose radiance is a texture (issue 17: every colour parameter may be a texture):
// light samples and BSDF-sampled hits both read the texel at the point, so a light made of a
// bright and a dim half lights a plane as the two halves' form factors say, and a constant
// texture renders the constant emitter's image.
#include "renderer/scene/scene_loader.h"
#include "sampling/core/errors.h"
#include "sampling/samplers/sampler.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace pdrt;
using namespace pdrt::test;

namespace {

int constant_texture(SceneDesc& s, float v) {
  TextureDesc t;
  t.kind = TextureDesc::Kind::Constant;
  t.value = Vec3(v);
  s.textures.push_back(t);
  return int(s.textures.size()) - 1;
}

Material textured_emitter(int texture, float scale) {
  Material m = emitter(scale);
  m.textures.push_back({MaterialParam::Radiance, texture});
  return m;
}

}  // namespace

// A quad light over [-0.5, 0.5]^2 at height 1, u along x: a checkerboard of 2 x 1 checks makes
// its x < 0 half radiance 4 and its x > 0 half 1. Each pixel of the diffuse plane below reads
// rho (4 F_left + F_right) at its centre (direct light, both strategies with MIS): the image
// mean within 0.5 % and each pixel within 8 % (1024 samples per pixel; a light whose radiance
// varies 4:1 leaves about 2 % noise per pixel, and the worst of 256 pixels is ~3.5 sigma).
// The swapped halves would be off by up to 46 %.
TEST(TexturedEmitters, AHalfBrightLightLightsThePlaneAsItsHalvesFormFactorsSay) {
  const int W = 16;
  const float rho = 0.8f, h = 1;
  SceneDesc s = base_scene(W, W, 1024);
  s.camera.position = {0, 0.5f, 0}, s.camera.look_at = {0, 0, 0}, s.camera.up = {0, 0, -1};
  s.camera.vfov_deg = 90;
  s.integrator.max_depth = 1;
  s.shapes.push_back(quad({-3, 0, -3}, {0, 0, 6}, {6, 0, 0}, add_material(s, diffuse(rho))));
  TextureDesc board;
  board.kind = TextureDesc::Kind::Checkerboard;
  board.scale_u = 2, board.scale_v = 1;
  board.color0.value = Vec3(1.0f), board.color1.value = Vec3(0.25f);
  s.textures.push_back(board);
  s.shapes.push_back(quad({-0.5f, h, -0.5f}, {1, 0, 0}, {0, 0, 1}, add_material(s, textured_emitter(0, 4))));
  Image im = render_quietly(s).image;
  double worst = 0, sum = 0, sum_expected = 0;
  for (int y = 0; y < W; ++y)
    for (int x = 0; x < W; ++x) {
      const double cx = (x + 0.5) / W - 0.5, cz = (y + 0.5) / W - 0.5;
      const double e = rho * (4 * rect_form_factor(cx, cz, -0.5, 0, -0.5, 0.5, h) +
                              1 * rect_form_factor(cx, cz, 0, 0.5, -0.5, 0.5, h));
      const double v = mean_rgb(im, x, y);
      worst = std::max(worst, std::abs(v / e - 1));
      sum += v, sum_expected += e;
    }
  EXPECT_NEAR(sum / sum_expected, 1, 0.005);
  EXPECT_LT(worst, 0.08);
  std::printf("half-bright light: mean ratio %.4f, worst pixel %.3f\n", sum / sum_expected, worst);
}

// The same half-bright light, scaled by 1e-3 and 1e5 and moved 1e4 from the origin, with
// every sampler and two seeds: each image half's mean (form factors are scale-invariant)
// within 3 % (64 samples per pixel over 128 pixels: about 0.7 % noise, 4 sigma). Swapping the
// light's halves would move them by 18 % and 22 %.
TEST(TexturedEmitters, AHalfBrightLightHoldsAtEveryScaleAndOffsetWithEverySamplerAndSeed) {
  const int W = 16;
  const float rho = 0.8f;
  double expect[2] = {0, 0};  // film columns x < W/2 (film x runs along +x here: the bright half's side), the rest
  for (int y = 0; y < W; ++y)
    for (int x = 0; x < W; ++x) {
      const double cx = (x + 0.5) / W - 0.5, cz = (y + 0.5) / W - 0.5;
      expect[x >= W / 2] +=
          rho * (4 * rect_form_factor(cx, cz, -0.5, 0, -0.5, 0.5, 1) + rect_form_factor(cx, cz, 0, 0.5, -0.5, 0.5, 1));
    }
  struct Frame {
    float scale;
    Vec3 offset;
  };
  for (const Frame& f : {Frame{1e-3f, Vec3(0.0f)}, Frame{1, Vec3(1e4f, -2e3f, 5e3f)}, Frame{1e5f, Vec3(0.0f)}})
    for (const std::string& sampler : sampler_names())
      for (uint64_t seed : {3u, 11u}) {
        SceneDesc s = base_scene(W, W, 64);
        s.sampler.type = sampler, s.sampler.seed = seed;
        auto at = [&](float x, float y, float z) { return f.offset + Vec3(x, y, z) * f.scale; };
        s.camera.position = at(0, 0.5f, 0), s.camera.look_at = at(0, 0, 0), s.camera.up = {0, 0, -1};
        s.camera.vfov_deg = 90;
        s.integrator.max_depth = 1;
        s.shapes.push_back(
            quad(at(-3, 0, -3), Vec3(0, 0, 6) * f.scale, Vec3(6, 0, 0) * f.scale, add_material(s, diffuse(rho))));
        TextureDesc board;
        board.kind = TextureDesc::Kind::Checkerboard;
        board.scale_u = 2, board.scale_v = 1;
        board.color0.value = Vec3(1.0f), board.color1.value = Vec3(0.25f);
        s.textures.push_back(board);
        s.shapes.push_back(quad(at(-0.5f, 1, -0.5f), Vec3(f.scale, 0, 0), Vec3(0, 0, f.scale),
                                add_material(s, textured_emitter(0, 4))));
        Image im = render_quietly(s).image;
        double got[2] = {0, 0};
        for (int y = 0; y < W; ++y)
          for (int x = 0; x < W; ++x) got[x >= W / 2] += mean_rgb(im, x, y);
        SCOPED_TRACE(sampler + " seed " + std::to_string(seed) + " scale " + std::to_string(f.scale) + " offset " +
                     std::to_string(f.offset.x));
        EXPECT_NEAR(got[0] / expect[0], 1, 0.03);
        EXPECT_NEAR(got[1] / expect[1], 1, 0.03);
      }
}

// A constant texture of 0.5 with scale 6 is the emitter of radiance 3: the same image (within
// 1e-6 relative: the one light is picked with probability 1 either way), for a quad light and
// for a sphere light, seen directly and lighting a plane.
TEST(TexturedEmitters, AConstantTextureRendersTheConstantEmittersImage) {
  for (bool sphere_light : {false, true}) {
    Image im[2];
    for (int textured = 0; textured < 2; ++textured) {
      SceneDesc s = base_scene(24, 16, 16);
      s.camera.position = {0, 2, 4}, s.camera.look_at = {0, 0.5f, 0}, s.camera.vfov_deg = 50;
      s.integrator.max_depth = 3;
      s.shapes.push_back(quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, add_material(s, diffuse(0.6f))));
      const int light =
          textured ? add_material(s, textured_emitter(constant_texture(s, 0.5f), 6)) : add_material(s, emitter(3));
      if (sphere_light) {
        s.shapes.push_back(sphere({0.3f, 1.2f, 0}, 0.4f, light));
      } else {
        s.shapes.push_back(quad({-0.5f, 1.5f, -0.5f}, {1, 0, 0}, {0, 0, 1}, light));
      }
      im[textured] = render_quietly(s).image;
    }
    double worst = 0, total = 0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 24; ++x) {
        const double a = mean_rgb(im[0], x, y), b = mean_rgb(im[1], x, y);
        total += a;
        worst = std::max(worst, std::abs(a - b) / std::max(a, 1e-3));
      }
    EXPECT_GT(total, 0);
    EXPECT_LT(worst, 1e-6) << (sphere_light ? "sphere" : "quad");
  }
}

TEST(TexturedEmitters, LoaderBindsARadianceTextureAndItsScale) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("pdrt_temit_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string head =
      R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]}, "film": {"width": 8, "height": 8},
 "textures": {"glow": {"type": "constant", "value": 0.5}},
 "materials": {"lamp": {"type": "emitter", )";
  const std::string tail = R"(}},
 "objects": [{"type": "sphere", "radius": 1, "material": "lamp"}]})";
  std::ofstream(dir / "a.json") << head << R"("radiance": "glow", "scale": [2, 4, 6])" << tail;
  SceneDesc s = load_scene(dir / "a.json");
  ASSERT_EQ(s.materials[0].textures.size(), 1u);
  EXPECT_EQ(s.materials[0].textures[0].param, MaterialParam::Radiance);
  EXPECT_EQ(s.materials[0].radiance.z, 6);
  std::ofstream(dir / "b.json") << head << R"("radiance": "glo")" << tail;
  try {
    load_scene(dir / "b.json");
    ADD_FAILURE() << "unknown texture accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown texture \"glo\""), std::string::npos) << e.what();
  }
  std::ofstream(dir / "c.json") << head << R"("radiance": [1, 1, 1], "scale": -1)" << tail;
  try {
    load_scene(dir / "c.json");
    ADD_FAILURE() << "negative scale accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials.lamp.scale"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}
