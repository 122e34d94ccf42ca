// pbrt-v4 world-block directives beyond shapes and materials (issue 18): `Attribute` defaults
// and their scoping, `loopsubdiv` refined through OpenSubdiv, and `infinite` lights with an
// equal-area octahedral image, resampled into pdrt's environment and written out by convert.
#include "renderer/render/embree_device.h"
#include "renderer/render/embree_scene.h"
#include "renderer/scene/equirect.h"
#include "renderer/image/image_output.h"
#include "renderer/scene/pbrt/equal_area_octahedral.h"
#include "renderer/scene/pbrt/pbrt_scene_builder.h"
#include "renderer/scene/scene_loader.h"
#include "renderer/scene/scene_writer.h"
#include "sampling/core/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <unistd.h>

using namespace pdrt;

namespace {

PbrtImport import(const std::string& text, bool strict = false) {
  return build_pbrt_scene(parse_pbrt_text(text, "s.pbrt", "."), strict);
}

std::string import_error(const std::string& text) {
  try {
    import(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError for: " << text;
  return "";
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("pdrt_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void expect_vec(const Vec3& a, const Vec3& b) {
  for (int c = 0; c < 3; ++c) EXPECT_EQ(a[c], b[c]) << "component " << c;
}

const std::string kWorld = "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n";

// An n x n octahedral image whose texel is `f` of its centre direction (light space).
void write_octahedral(const std::filesystem::path& file, int n, Vec3 (*f)(const Vec3&)) {
  std::vector<float> rgb;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Vec3 v = f(equal_area_square_to_sphere((x + 0.5) / n, (y + 0.5) / n));
      rgb.insert(rgb.end(), {v.x, v.y, v.z});
    }
  write_linear_rgb(file, n, n, rgb, {});
}

Vec3 sky(const Vec3& w) { return w.z > 0 ? Vec3(2, 1, 0.5f) : Vec3(0.0f); }  // bright above light-space z = 0

}  // namespace

TEST(PbrtWorldBlock, AttributeSetsDefaultsForLaterDirectivesOfItsKind) {
  PbrtImport im = import(kWorld +
                         "AttributeBegin\n"
                         "  Attribute \"shape\" \"float radius\" 0.25\n"
                         "  Shape \"sphere\"\n"
                         "  Shape \"sphere\" \"float radius\" 2\n"  // its own value wins
                         "  Attribute \"material\" \"rgb reflectance\" [0.1 0.2 0.3]\n"
                         "  Material \"diffuse\"\n"
                         "  Shape \"sphere\"\n"
                         "AttributeEnd\n"
                         "Shape \"sphere\"\n");  // out of scope again
  ASSERT_EQ(im.scene.shapes.size(), 4u);
  EXPECT_EQ(im.scene.shapes[0].radius, 0.25f);
  EXPECT_EQ(im.scene.shapes[1].radius, 2.0f);
  EXPECT_EQ(im.scene.shapes[2].radius, 0.25f);
  EXPECT_EQ(im.scene.shapes[3].radius, 1.0f);
  const Material& m = im.scene.materials[size_t(im.scene.shapes[2].material)];
  expect_vec(m.albedo, Vec3(0.1f, 0.2f, 0.3f));
  // A default the directive does not read is not reported; the directive's own unused ones are.
  PbrtImport r = import(kWorld + "Attribute \"shape\" \"float zzz\" 1\nShape \"sphere\" \"float yyy\" 2\n");
  ASSERT_EQ(r.report.size(), 1u);
  EXPECT_EQ(r.report[0], "s.pbrt:5:16: \"float yyy\" is not used by pdrt (ignored)");
  // A later Attribute replaces an earlier value of the same name.
  PbrtImport l = import(
      kWorld + "Attribute \"shape\" \"float radius\" 3\nAttribute \"shape\" \"float radius\" 4\nShape \"sphere\"\n");
  EXPECT_EQ(l.scene.shapes[0].radius, 4.0f);
  // Light attributes reach area lights too.
  PbrtImport a =
      import(kWorld + "Attribute \"light\" \"float scale\" 3\nAreaLightSource \"diffuse\"\nShape \"sphere\"\n");
  expect_vec(a.scene.materials[size_t(a.scene.shapes[0].material)].radiance, Vec3(3.0f));
}

TEST(PbrtWorldBlock, AttributeTargetsAreCheckedAndMediumIsReported) {
  EXPECT_EQ(import_error(kWorld + "Attribute \"camera\" \"float fov\" 3\n"),
            "s.pbrt:4:1: Attribute target must be \"shape\", \"light\", \"material\", \"medium\" or \"texture\", got "
            "\"camera\"");
  PbrtImport m = import(kWorld + "Attribute \"medium\" \"rgb sigma_a\" [1 1 1]\nShape \"sphere\"\n");
  ASSERT_EQ(m.report.size(), 1u);
  EXPECT_EQ(m.report[0],
            "s.pbrt:4:1: Attribute \"medium\" is not supported: pdrt has no participating media (ignored)");
}

TEST(PbrtWorldBlock, LoopSubdivRefinesToTheRequestedLevelWithLimitNormals) {
  const std::string tetra =
      "Shape \"loopsubdiv\" \"point3 P\" [1 1 1  1 -1 -1  -1 1 -1  -1 -1 1] "
      "\"integer indices\" [0 1 2  0 3 1  0 2 3  1 3 2]";
  PbrtImport im = import(kWorld + tetra + " \"integer levels\" 2\n" + tetra + "\n");
  ASSERT_EQ(im.scene.shapes.size(), 2u);
  EXPECT_TRUE(im.report.empty()) << im.report[0];
  const MeshData& m = im.scene.shapes[0].mesh;
  EXPECT_EQ(m.indices.size(), 3u * 4 * 16);                        // 4 faces x 4^2
  EXPECT_EQ(im.scene.shapes[1].mesh.indices.size(), 3u * 4 * 64);  // pbrt-v4's default: 3 levels
  ASSERT_EQ(m.normals.size(), m.positions.size());
  // The control faces wind outward, so do the normals and the refined faces.
  for (size_t i = 0; i < m.positions.size(); ++i) EXPECT_GT(dot(m.normals[i], m.positions[i]), 0) << i;
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    const Vec3 &a = m.positions[m.indices[i]], &b = m.positions[m.indices[i + 1]], &c = m.positions[m.indices[i + 2]];
    EXPECT_GT(dot(cross(b - a, c - a), a + b + c), 0) << "face " << i / 3;
  }
  // The limit surface lies inside the control hull: every point strictly within |x|,|y|,|z| < 1.
  for (const Vec3& p : m.positions) EXPECT_LT(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 1.0f);
  EXPECT_EQ(import_error(kWorld + tetra + " \"integer levels\" -1\n"),
            "s.pbrt:4:113: \"integer levels\" must be in [0, 12], got -1");
}

TEST(PbrtWorldBlock, InfiniteLightImageBecomesTheEquirectangularEnvironment) {
  const auto dir = scratch("pbrt_envmap");
  write_octahedral(dir / "sky.exr", 32, sky);
  // pbrt scenes usually turn the map's +z to the world's +y.
  std::ofstream(dir / "s.pbrt") << kWorld << "AttributeBegin\nRotate -90 1 0 0\n"
                                << "LightSource \"infinite\" \"string filename\" \"sky.exr\" \"float scale\" 1.5\n"
                                << "AttributeEnd\nShape \"sphere\"\n";
  PbrtImport im = load_pbrt_scene(dir / "s.pbrt", false);
  // pbrt-v4 looks up the nearest texel, pdrt interpolates its resampled map: reported, and
  // refused by --strict.
  const std::string note = (dir / "s.pbrt").string() +
                           ":6:24: \"sky.exr\" is resampled to pdrt's equirectangular map and interpolated, where "
                           "pbrt-v4 shows its nearest texel: texel edges seen directly are soft";
  EXPECT_EQ(im.report, std::vector<std::string>{note});
  EXPECT_THROW(
      try { load_pbrt_scene(dir / "s.pbrt", true); } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), note + " [--strict]");
        throw;
      },
      InputError);
  EXPECT_EQ(im.scene.integrator.environment_sampling, EnvironmentSampling::Compensated);
  const EnvironmentDesc& e = im.scene.environment;
  ASSERT_TRUE(e.has_map());
  EXPECT_EQ(e.width, 64);
  EXPECT_EQ(e.height, 32);
  expect_vec(e.scale, Vec3(1.5f));
  EXPECT_TRUE(e.resampled);
  // Rows well above the horizon hold the sky, rows well below it black.
  for (int i = 0; i < e.width; ++i) {
    EXPECT_NEAR(e.rgb[3 * (2 * e.width + i)], 2, 1e-5) << "column " << i;
    EXPECT_EQ(e.rgb[3 * (29 * e.width + i)], 0) << "column " << i;
  }
  // illuminance: a sky of luminance lum over the upper hemisphere gives E = pi lum, so asking
  // for E = pi scales by 1 / lum. (The luminance of (2, 1, 0.5) in linear sRGB.)
  std::ofstream(dir / "e.pbrt")
      << kWorld << "LightSource \"infinite\" \"string filename\" \"sky.exr\" \"float illuminance\" 3.14159265\n"
      << "Shape \"sphere\"\n";
  const double lum = 0.2126 * 2 + 0.7152 * 1 + 0.0722 * 0.5;
  EXPECT_NEAR(load_pbrt_scene(dir / "e.pbrt", false).scene.environment.scale.x, 1 / lum, 5e-3 / lum);
}

TEST(PbrtWorldBlock, InfiniteLightImageErrorsNameTheParameter) {
  const auto dir = scratch("pbrt_envmap_errors");
  write_linear_rgb(dir / "wide.exr", 4, 2, std::vector<float>(24, 1.0f), {});
  auto error = [&](const std::string& params) {
    std::ofstream(dir / "s.pbrt") << kWorld << "LightSource \"infinite\" \"string filename\" " << params << "\n";
    try {
      load_pbrt_scene(dir / "s.pbrt", false);
    } catch (const InputError& e) {
      return std::string(e.what()).substr((dir / "s.pbrt").string().size());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("\"wide.exr\""),
            ":4:24: \"wide.exr\" is 4 x 2: pbrt-v4's environment images are square (equal-area octahedral)");
  EXPECT_EQ(error("\"none.exr\"").substr(0, 31), ":4:24: cannot read \"none.exr\": ");
  EXPECT_EQ(error("\"wide.exr\" \"rgb L\" [1 1 1]"), ":4:53: an infinite light takes \"L\" or \"filename\", not both");
}

TEST(PbrtWorldBlock, ConvertWritesTheResampledEnvironmentBesideTheScene) {
  const auto dir = scratch("pbrt_envmap_convert");
  write_octahedral(dir / "sky.exr", 16, sky);
  std::ofstream(dir / "s.pbrt") << kWorld
                                << "LightSource \"infinite\" \"string filename\" \"sky.exr\"\nShape \"sphere\"\n";
  PbrtImport im = load_pbrt_scene(dir / "s.pbrt", false);
  write_scene_json(im.scene, dir / "out.json");
  ASSERT_TRUE(std::filesystem::exists(dir / "out.environment.exr"));
  SceneDesc back = load_scene(dir / "out.json");
  ASSERT_TRUE(back.environment.has_map());
  EXPECT_FALSE(back.environment.resampled);
  EXPECT_EQ(back.environment.width, im.scene.environment.width);
  EXPECT_EQ(back.environment.rgb, im.scene.environment.rgb);  // EXR float: exact
}

TEST(PbrtWorldBlock, SphereUvFollowPbrtsPoleAndAzimuth) {
  // pbrt-v4: u = phi / 2 pi with phi from +x toward +y, v = 1 - theta / pi with theta from +z;
  // for a static sphere and for a moving one (its transform then lives in the instance).
  for (const std::string motion : {"", "ActiveTransform EndTime\nTranslate 0 0 0.5\nActiveTransform All\n"}) {
    PbrtImport im = import(kWorld + "Translate 1 2 3\n" + motion + "Shape \"sphere\" \"float radius\" 2\n");
    EmbreeDevice dev;
    EmbreeScene scene(im.scene, dev);
    const Vec3 c(1, 2, 3);
    struct Case {
      Vec3 dir;
      float u, v;
    };
    const float h = std::sqrt(0.5f);
    for (const Case& k :
         {Case{{1, 0, 0}, 0.0f, 0.5f}, Case{{0, 1, 0}, 0.25f, 0.5f}, Case{{-1, 0, 0}, 0.5f, 0.5f},
          Case{{0, -1, 0}, 0.75f, 0.5f}, Case{{h, 0, h}, 0.0f, 0.75f}, Case{{0, h, -h}, 0.25f, 0.25f}}) {
      Ray r;
      r.org = c + k.dir * 10, r.dir = -k.dir, r.time = 0;
      SurfaceHit hit;
      ASSERT_TRUE(scene.intersect(r, &hit));
      scene.texture_coords(&hit, 0);
      EXPECT_NEAR(hit.u, k.u, 1e-5f) << motion << k.dir.x << " " << k.dir.y << " " << k.dir.z;
      EXPECT_NEAR(hit.v, k.v, 1e-5f) << motion << k.dir.x << " " << k.dir.y << " " << k.dir.z;
      EXPECT_GT(dot(hit.ng, k.dir), 0.999f);  // still facing outward
    }
  }
}
