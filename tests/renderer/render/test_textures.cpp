// Texture evaluation (renderer/render/texture_set.h): point sampling returns texels exactly,
// MIP filters preserve a constant, sRGB is decoded, the checkerboard's parity and its mean,
// and a constant texture builds the very material its value does.
#include "renderer/render/bsdf.h"
#include "renderer/image/image_module.h"
#include "renderer/render/texture_set.h"
#include "sampling/core/errors.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace pdrt;
using namespace pdrt::test;

namespace {

fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir =
      fs::temp_directory_path() / ("pdrt_tex_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

// Writes an image through the image module: `px` is width * height * 3 floats, top row first.
fs::path write_image(const fs::path& file, const char* format, int w, int h, const std::vector<float>& px, bool uint8) {
  PdrtImageWrite iw{};
  const std::string path = file.string();
  iw.path = path.c_str(), iw.format = format;
  iw.width = w, iw.height = h, iw.channels = 3;
  iw.z_channel = -1, iw.uint8 = uint8 ? 1 : 0;
  iw.pixels = px.data();
  char error[256] = "";
  EXPECT_EQ(image_module().write(&iw, error, sizeof error), 0) << error;
  return file;
}

TextureDesc image_texture(const fs::path& file, TextureFilter f, TextureWrap w = TextureWrap::Repeat) {
  TextureDesc t;
  t.kind = TextureDesc::Kind::Image;
  t.name = "image";
  t.where = "test";
  t.file = file;
  t.filter = f;
  t.wrap = w;
  return t;
}

SceneDesc with_textures(std::vector<TextureDesc> t) {
  SceneDesc s;
  s.textures = std::move(t);
  return s;
}

TextureCoords at(float u, float v, float d = 0) {
  TextureCoords tc;
  tc.u = u, tc.v = v, tc.dudx = d, tc.dvdy = d;
  return tc;
}

class Textures : public ::testing::Test {
 protected:
  void TearDown() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::error_code ec;
    fs::remove_all(
        fs::temp_directory_path() / ("pdrt_tex_" + std::string(info->name()) + "_" + std::to_string(::getpid())), ec);
  }
};

// 4 x 3 texels, all values distinct: texel (i, j) (column i, row j from the top).
constexpr int kW = 4, kH = 3;
Vec3 texel(int i, int j) {
  const float x = float(i + kW * j + 1) / 16.0f;
  return {x, 0.5f * x + 0.25f, 1 - x};
}
std::vector<float> texels() {
  std::vector<float> px;
  for (int j = 0; j < kH; ++j)
    for (int i = 0; i < kW; ++i) {
      Vec3 c = texel(i, j);
      px.insert(px.end(), {c.x, c.y, c.z});
    }
  return px;
}

}  // namespace

// filter "none": anywhere inside a texel, exactly that texel's value (float EXR: read unchanged).
TEST_F(Textures, PointSamplingReturnsTexelValuesExactly) {
  fs::path f = write_image(temp_dir() / "t.exr", "exr", kW, kH, texels(), false);
  TextureSet ts(with_textures({image_texture(f, TextureFilter::None)}));
  int checked = 0;
  for (int j = 0; j < kH; ++j)
    for (int i = 0; i < kW; ++i)
      for (float fu : {0.05f, 0.5f, 0.95f})
        for (float fv : {0.05f, 0.5f, 0.95f}) {
          // v runs up the image: row j spans v in (1 - (j + 1) / H, 1 - j / H).
          const float u = (i + fu) / kW, v = 1 - (j + fv) / kH;
          const Vec3 got = ts.eval(0, at(u, v, 0.3f)), want = texel(i, j);  // the footprint is ignored
          EXPECT_EQ(got.x, want.x) << i << "," << j;
          EXPECT_EQ(got.y, want.y) << i << "," << j;
          EXPECT_EQ(got.z, want.z) << i << "," << j;
          ++checked;
        }
  EXPECT_EQ(checked, kW * kH * 9);
}

// Out-of-range uv under each wrap mode: repeat shifts by whole periods, mirror reflects,
// clamp takes the edge texel, black gives 0; all point-sampled exactly.
TEST_F(Textures, PointSamplingHonoursEveryWrapModeExactly) {
  fs::path f = write_image(temp_dir() / "t.exr", "exr", kW, kH, texels(), false);
  TextureSet ts(with_textures({image_texture(f, TextureFilter::None, TextureWrap::Repeat),
                               image_texture(f, TextureFilter::None, TextureWrap::Mirror),
                               image_texture(f, TextureFilter::None, TextureWrap::Clamp),
                               image_texture(f, TextureFilter::None, TextureWrap::Black)}));
  auto same = [](const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
  for (int j = 0; j < kH; ++j)
    for (int i = 0; i < kW; ++i) {
      const float u = (i + 0.4f) / kW, v = 1 - (j + 0.6f) / kH;
      const Vec3 want = texel(i, j);
      EXPECT_TRUE(same(ts.eval(0, at(u + 2, v - 3)), want)) << "repeat " << i << "," << j;
      EXPECT_TRUE(same(ts.eval(0, at(u - 1, v + 1)), want)) << "repeat " << i << "," << j;
      EXPECT_TRUE(same(ts.eval(1, at(-u, v)), want)) << "mirror " << i << "," << j;
      EXPECT_TRUE(same(ts.eval(2, at(u - 5, v)), texel(0, j))) << "clamp " << i << "," << j;
      EXPECT_TRUE(same(ts.eval(2, at(u + 5, v)), texel(kW - 1, j))) << "clamp " << i << "," << j;
      EXPECT_TRUE(same(ts.eval(2, at(u, v + 7)), texel(i, 0))) << "clamp " << i << "," << j;  // above the top row
      EXPECT_TRUE(same(ts.eval(3, at(u + 1.5f, v)), Vec3(0.0f))) << "black " << i << "," << j;
      EXPECT_TRUE(same(ts.eval(3, at(u, v - 2)), Vec3(0.0f))) << "black " << i << "," << j;
    }
}

// Coordinates and footprints no scene should produce, but a user's "uvs" can (1e30, and
// inf/NaN after scaling): every filter and wrap mode returns a finite texel value or black.
TEST_F(Textures, ExtremeCoordinatesGiveFiniteValues) {
  fs::path f = write_image(temp_dir() / "t.exr", "exr", kW, kH, texels(), false);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (TextureFilter filter :
       {TextureFilter::None, TextureFilter::Bilinear, TextureFilter::Trilinear, TextureFilter::Ewa})
    for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::Mirror, TextureWrap::Clamp, TextureWrap::Black}) {
      TextureSet ts(with_textures({image_texture(f, filter, wrap)}));
      for (float x : {1e30f, -1e30f, 3e7f, inf, -inf, nan})
        for (float d : {0.0f, 1e30f, nan}) {
          const Vec3 a = ts.eval(0, at(x, 0.3f, d)), b = ts.eval(0, at(0.3f, x, d));
          EXPECT_TRUE(is_finite(a) && is_finite(b)) << int(filter) << " " << int(wrap) << " " << x << " " << d;
          EXPECT_LE(std::max(a.x, b.x), 1.0f);
        }
    }
}

// MIP-mapped lookups of a constant image return the constant for tiny, unit, huge and
// anisotropic footprints (each level is a normalised filter of the one above).
TEST_F(Textures, MipMappedLookupsOfAConstantReturnTheConstant) {
  const Vec3 c(0.3f, 0.6f, 0.9f);
  std::vector<float> px;
  for (int k = 0; k < 64 * 48; ++k) px.insert(px.end(), {c.x, c.y, c.z});
  fs::path f = write_image(temp_dir() / "c.exr", "exr", 64, 48, px, false);
  for (TextureFilter filter : {TextureFilter::Bilinear, TextureFilter::Trilinear, TextureFilter::Ewa}) {
    TextureSet ts(with_textures({image_texture(f, filter)}));
    for (float d : {0.0f, 1e-4f, 0.05f, 1.0f, 50.0f}) {
      for (auto [u, v] : {std::pair{0.3f, 0.7f}, std::pair{0.01f, 0.99f}, std::pair{-3.2f, 5.1f}}) {
        TextureCoords tc = at(u, v, d);
        const Vec3 got = ts.eval(0, tc);
        EXPECT_NEAR(got.x, c.x, 1e-5f) << int(filter) << " d=" << d;
        EXPECT_NEAR(got.y, c.y, 1e-5f) << int(filter) << " d=" << d;
        EXPECT_NEAR(got.z, c.z, 1e-5f) << int(filter) << " d=" << d;
        tc.dudx = 0.5f, tc.dvdx = 0, tc.dudy = 0, tc.dvdy = 1e-3f;  // 500:1 anisotropic
        const Vec3 aniso = ts.eval(0, tc);
        EXPECT_NEAR(aniso.x, c.x, 1e-5f) << int(filter) << " anisotropic";
        EXPECT_NEAR(aniso.z, c.z, 1e-5f) << int(filter) << " anisotropic";
      }
    }
  }
}

// An 8-bit PNG texel of 128 is sRGB-encoded: ((128/255 + 0.055) / 1.055)^2.4 = 0.21586 linear
// (encoding "auto" and "srgb"); "linear" takes the code value as is, 128/255.
TEST_F(Textures, EightBitImagesAreDecodedFromSrgb) {
  std::vector<float> px;
  for (int k = 0; k < 4; ++k) px.insert(px.end(), {128 / 255.0f, 128 / 255.0f, 128 / 255.0f});
  fs::path f = write_image(temp_dir() / "g.png", "png", 2, 2, px, true);
  TextureDesc automatic = image_texture(f, TextureFilter::None), srgb = automatic, linear = automatic;
  srgb.encoding = TextureEncoding::Srgb, linear.encoding = TextureEncoding::Linear;
  TextureSet ts(with_textures({automatic, srgb, linear, image_texture(f, TextureFilter::Trilinear)}));
  const double decoded = std::pow((128 / 255.0 + 0.055) / 1.055, 2.4);
  EXPECT_NEAR(decoded, 0.21586, 1e-5);
  EXPECT_NEAR(ts.eval(0, at(0.3f, 0.3f)).y, decoded, 2e-4);
  EXPECT_NEAR(ts.eval(1, at(0.7f, 0.2f)).x, decoded, 2e-4);
  EXPECT_NEAR(ts.eval(2, at(0.3f, 0.3f)).z, 128 / 255.0, 1e-5);
  // Decoded before filtering: a MIP lookup of the constant image is the decoded constant.
  EXPECT_NEAR(ts.eval(3, at(0.5f, 0.5f, 0.8f)).x, decoded, 2e-4);
}

// Decoding comes before filtering: the coarsest MIP level of black and white 8-bit texels is
// the mean of their linear values, 0.5 (filtering the codes first would give 128 -> 0.216).
TEST_F(Textures, SrgbIsDecodedBeforeMipFiltering) {
  std::vector<float> px = {0, 0, 0, 1, 1, 1, 0, 0, 0, 1, 1, 1};
  fs::path f = write_image(temp_dir() / "bw.png", "png", 2, 2, px, true);
  TextureSet ts(with_textures({image_texture(f, TextureFilter::Trilinear)}));
  EXPECT_NEAR(ts.eval(0, at(0.5f, 0.5f, 20.0f)).x, 0.5, 1e-3);
  EXPECT_EQ(ts.eval(0, at(0.5f, 0.5f, 20.0f)).x, ts.eval(0, at(0.1f, 0.8f, 20.0f)).x);
}

// pbrt-v4's 2-D checkerboard: color0 where floor(u su) + floor(v sv) is even.
TEST_F(Textures, CheckerboardParityAtKnownUv) {
  TextureDesc red, board;
  red.kind = TextureDesc::Kind::Constant, red.value = Vec3(1, 0, 0);
  board.kind = TextureDesc::Kind::Checkerboard;
  board.scale_u = 4, board.scale_v = 2;
  board.color0.texture = 1;  // a texture as a colour
  board.color1.value = Vec3(0.25f);
  TextureSet ts(with_textures({board, red}));
  auto is_red = [&](float u, float v) { return ts.eval(0, at(u, v)).x == 1.0f; };
  EXPECT_TRUE(is_red(0.1f, 0.1f));    // (0, 0)
  EXPECT_FALSE(is_red(0.3f, 0.1f));   // (1, 0)
  EXPECT_FALSE(is_red(0.1f, 0.6f));   // (0, 1)
  EXPECT_TRUE(is_red(0.3f, 0.6f));    // (1, 1)
  EXPECT_FALSE(is_red(-0.1f, 0.1f));  // (-1, 0)
  EXPECT_TRUE(is_red(-0.1f, -0.1f));  // (-1, -1)
  EXPECT_TRUE(is_red(2.6f, 0.1f));    // (10, 0)
  EXPECT_EQ(ts.eval(0, at(0.3f, 0.1f)).y, 0.25f);
}

// A plane of 60 x 60 checks per pixel, 16 samples each: the albedo AOV's image mean is the
// mean of the two colours. Samples are (nearly) independent of the checks, so the mean of
// 16384 two-valued samples has standard deviation (0.8 - 0.2) / 2 / 128 = 0.0023; ±0.01 is 4 sigma.
TEST_F(Textures, CheckerboardPlaneMeanConvergesToTheMeanOfItsColours) {
  const int W = 32;
  SceneDesc s = base_scene(W, W, 16);
  s.camera.position = {0, 1, 0}, s.camera.look_at = {0, 0, 0}, s.camera.up = {0, 0, -1};
  s.camera.vfov_deg = 60;
  TextureDesc board;
  board.kind = TextureDesc::Kind::Checkerboard;
  board.scale_u = board.scale_v = 1000;
  board.color0.value = Vec3(0.2f), board.color1.value = Vec3(0.8f);
  s.textures.push_back(board);
  Material m = diffuse(0.5f);
  m.textures.push_back({MaterialParam::Albedo, 0});
  s.environment.radiance = Vec3(1.0f);
  s.integrator.max_depth = 1;
  s.shapes.push_back(quad({-2, 0, -2}, {0, 0, 4}, {4, 0, 0}, add_material(s, m)));  // 1000 checks per 4 units
  const Image im = render_quietly(s).image;
  double albedo = 0, radiance = 0;
  for (int k = 0; k < W * W; ++k) albedo += im.albedo[3 * k], radiance += im.rgb[3 * k + 1];
  std::printf("checkerboard plane: albedo AOV mean %.4f, radiance mean %.4f (both 0.5 in the limit)\n",
              albedo / (W * W), radiance / (W * W));
  EXPECT_NEAR(albedo / (W * W), 0.5, 0.01);
  // Lit by a white environment with one bounce, a diffuse plane shows its albedo (furnace).
  EXPECT_NEAR(radiance / (W * W), 0.5, 0.01);
}

// A textured parameter evaluated to v builds a BSDF identical to the constant v, for every
// material type with such parameters: values, pdfs and samples bit for bit.
TEST_F(Textures, ConstantTextureBuildsTheSameBsdfAsTheConstantValue) {
  TextureDesc grey, rough;
  grey.kind = rough.kind = TextureDesc::Kind::Constant;
  grey.value = Vec3(0.35f, 0.5f, 0.65f), rough.value = Vec3(0.4f, 0.9f, 0.9f);  // roughness: the first channel
  TextureSet ts(with_textures({grey, rough}));
  struct Case {
    MaterialType type;
    bool albedo, roughness;
  };
  const Case cases[] = {{MaterialType::Diffuse, true, false},
                        {MaterialType::Glossy, true, true},
                        {MaterialType::Mirror, true, false},
                        {MaterialType::Dielectric, true, true},
                        {MaterialType::Conductor, false, true}};
  for (const Case& c : cases) {
    Material constant;
    constant.type = c.type;
    constant.albedo = grey.value;
    constant.roughness = c.roughness ? 0.4f : 0.0f;
    constant.eta = Vec3(0.2f, 0.9f, 1.1f), constant.k = Vec3(3.0f, 2.5f, 2.2f);
    Material bare = constant;
    std::vector<TextureBinding> bind;
    if (c.albedo) bare.albedo = Vec3(0.9f), bind.push_back({MaterialParam::Albedo, 0});
    if (c.roughness) bare.roughness = 0, bind.push_back({MaterialParam::Roughness, 1});
    const Bsdf a(constant), b(ts.apply(bare, bind, at(0.3f, 0.4f)));
    EXPECT_EQ(a.albedo().x, b.albedo().x);
    EXPECT_EQ(a.is_delta(), b.is_delta());
    const Vec3 wo = normalize(Vec3(0.3f, -0.2f, 0.9f));
    for (float u1 : {0.1f, 0.5f, 0.83f})
      for (float uc : {0.2f, 0.7f}) {
        BsdfSample sa, sb;
        const bool oka = a.sample(wo, u1, 0.37f, uc, &sa), okb = b.sample(wo, u1, 0.37f, uc, &sb);
        ASSERT_EQ(oka, okb);
        if (!oka) continue;
        EXPECT_EQ(std::memcmp(&sa.wi, &sb.wi, sizeof sa.wi), 0) << int(c.type);
        EXPECT_EQ(std::memcmp(&sa.weight, &sb.weight, sizeof sa.weight), 0) << int(c.type);
        EXPECT_EQ(sa.pdf, sb.pdf);
        const Vec3 fa = a.eval(wo, sa.wi), fb = b.eval(wo, sa.wi);
        EXPECT_EQ(std::memcmp(&fa, &fb, sizeof fa), 0) << int(c.type);
        EXPECT_EQ(a.pdf(wo, sa.wi), b.pdf(wo, sa.wi));
      }
  }
}

// The same through the whole renderer: one sphere per textured material type, with constant
// textures or with their values, gives the same image bit for bit (and so does a 1 x 1 image).
TEST_F(Textures, ConstantTexturesRenderTheSameImageAsConstantValues) {
  std::vector<float> one = {0.35f, 0.5f, 0.65f};
  fs::path f = write_image(temp_dir() / "one.exr", "exr", 1, 1, one, false);
  auto build = [&](int mode) {  // 0: values, 1: constant textures, 2: a 1 x 1 image (point-sampled)
    SceneDesc s = base_scene(24, 16, 4);
    s.camera.position = {0, 0, 9}, s.camera.look_at = {0, 0, 0};
    s.environment.radiance = Vec3(0.8f);
    TextureDesc grey, rough;
    grey.kind = rough.kind = TextureDesc::Kind::Constant;
    grey.value = Vec3(0.35f, 0.5f, 0.65f), rough.value = Vec3(0.35f);
    s.textures = {mode == 2 ? image_texture(f, TextureFilter::None) : grey, rough};
    const MaterialType types[] = {MaterialType::Diffuse, MaterialType::Glossy, MaterialType::Mirror,
                                  MaterialType::Dielectric, MaterialType::Conductor};
    for (int i = 0; i < 5; ++i) {
      Material m;
      m.type = types[i];
      m.albedo = Vec3(0.35f, 0.5f, 0.65f);
      m.roughness = types[i] == MaterialType::Mirror || types[i] == MaterialType::Diffuse ? 0.0f : 0.35f;
      m.eta = Vec3(0.2f, 0.9f, 1.1f), m.k = Vec3(3.0f, 2.5f, 2.2f);
      if (mode) {
        if (types[i] != MaterialType::Conductor)
          m.albedo = Vec3(1.0f), m.textures.push_back({MaterialParam::Albedo, 0});
        if (m.roughness > 0) m.roughness = 0.9f, m.textures.push_back({MaterialParam::Roughness, 1});
      }
      s.shapes.push_back(sphere({-4.0f + 2 * i, 0, 0}, 0.9f, add_material(s, m)));
    }
    return s;
  };
  const Image a = render_quietly(build(0), 1).image, b = render_quietly(build(1), 1).image,
              c = render_quietly(build(2), 1).image;
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  EXPECT_EQ(std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(a.albedo.data(), b.albedo.data(), a.albedo.size() * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(a.rgb.data(), c.rgb.data(), a.rgb.size() * sizeof(float)), 0);
}

// A colour texture drives a roughness by its first channel; values beyond [0, 1] are clamped.
TEST_F(Textures, ScalarParametersTakeTheFirstChannelClampedToTheUnitInterval) {
  std::vector<float> px = {1.7f, 0.1f, 0.1f, -0.5f, 0.9f, 0.9f};
  fs::path f = write_image(temp_dir() / "r.exr", "exr", 2, 1, px, false);
  TextureSet ts(with_textures({image_texture(f, TextureFilter::None)}));
  Material m;
  m.type = MaterialType::Glossy;
  const std::vector<TextureBinding> rough = {{MaterialParam::Roughness, 0}}, albedo = {{MaterialParam::Albedo, 0}};
  EXPECT_EQ(ts.apply(m, rough, at(0.25f, 0.5f)).roughness, 1.0f);
  EXPECT_EQ(ts.apply(m, rough, at(0.75f, 0.5f)).roughness, 0.0f);
  const Vec3 a = ts.apply(m, albedo, at(0.25f, 0.5f)).albedo;
  EXPECT_EQ(a.x, 1.0f);
  EXPECT_EQ(a.y, 0.1f);
}

// A missing or unreadable image is refused before rendering, naming the texture's key.
TEST_F(Textures, UnreadableImageIsRefusedNamingItsKey) {
  fs::path f = temp_dir() / "bad.png";
  std::ofstream(f) << "not a png";
  TextureDesc t = image_texture(f, TextureFilter::None);
  t.where = "s.json:4:30: textures.wood.file";
  try {
    TextureSet ts(with_textures({t}));
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("s.json:4:30: textures.wood.file: cannot use ", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}
