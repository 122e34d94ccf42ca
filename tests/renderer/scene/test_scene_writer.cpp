// `pdrt convert` (issue 18): a scene written as pdrt JSON loads back into a description that
// renders the same image, for the complete example (every key of the format) and for an
// imported pbrt-v4 scene; bad output paths are refused.
#include "renderer/scene/pbrt/pbrt_scene_builder.h"
#include "renderer/scene/scene_loader.h"
#include "renderer/scene/scene_writer.h"
#include "tests/support/cli_runner.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace pdrt;
using namespace pdrt::test;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir =
      fs::temp_directory_path() / ("pdrt_writer_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Renders both at a small size and few samples; returns the largest per-pixel difference
// relative to the image mean.
double image_difference(SceneDesc a, SceneDesc b) {
  for (SceneDesc* s : {&a, &b}) {
    s->film.width = 40, s->film.height = 30, s->sampler.spp = 4;
    s->sampler.adaptive.enabled = false;
  }
  Image x = render_quietly(a).image, y = render_quietly(b).image;
  EXPECT_EQ(x.width, y.width);  // less than 40 x 30 under a crop window
  EXPECT_EQ(x.height, y.height);
  double worst = 0, mean = 0;
  for (int j = 0; j < std::min(x.height, y.height); ++j)
    for (int i = 0; i < std::min(x.width, y.width); ++i)
      worst = std::max(worst, std::abs(mean_rgb(x, i, j) - mean_rgb(y, i, j))), mean += mean_rgb(y, i, j);
  mean /= double(std::min(x.width, y.width)) * std::min(x.height, y.height);
  EXPECT_GT(mean, 0);
  return worst / std::max(mean, 1e-9);
}

}  // namespace

TEST(SceneWriter, TheCompleteExampleRoundTripsToTheSameImage) {
  const fs::path dir = temp_dir();
  SceneDesc s = load_scene(fs::path(PDRT_EXAMPLES_DIR) / "all-features.json");
  write_scene_json(s, dir / "out.json");
  SceneDesc back = load_scene(dir / "out.json");
  EXPECT_EQ(back.shapes.size(), s.shapes.size());
  EXPECT_EQ(back.materials.size(), s.materials.size());
  EXPECT_EQ(back.textures.size(), s.textures.size());
  EXPECT_EQ(back.delta_lights.size(), s.delta_lights.size());
  EXPECT_EQ(back.camera.motion.size(), s.camera.motion.size());
  EXPECT_EQ(back.camera.projection, s.camera.projection);
  EXPECT_EQ(back.camera.ortho_height, s.camera.ortho_height);
  EXPECT_EQ(back.camera.has_screen_window, s.camera.has_screen_window);
  EXPECT_EQ(back.camera.screen_window, s.camera.screen_window);
  EXPECT_EQ(back.film.crop_window, s.film.crop_window);
  // Floats are written so they read back exactly; rotations go through an axis and angle, so
  // a moving object can differ in the last bits (measured: 0 here).
  EXPECT_LT(image_difference(s, back), 1e-3);
  fs::remove_all(dir);
}

TEST(SceneWriter, AnImportedPbrtSceneRoundTripsToTheSameImage) {
  const fs::path dir = temp_dir();
  std::ofstream(dir / "s.pbrt")
      << "LookAt 0 2 -5  0 0.5 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" 40\n"
         "WorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [0.3 0.3 0.35]\n"
         "LightSource \"spot\" \"point3 from\" [0 4 0] \"point3 to\" [0 0 0] \"rgb I\" [20 20 20]\n"
         "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8\n"
         "Material \"coateddiffuse\" \"texture reflectance\" \"checks\" \"float roughness\" 0.1\n"
         "Shape \"trianglemesh\" \"point3 P\" [-3 0 -3 3 0 -3 3 0 3 -3 0 3] \"integer indices\" [0 1 2 0 2 3]"
         " \"point2 uv\" [0 0 1 0 1 1 0 1]\n"
         "AttributeBegin\n"
         "  Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\" \"float roughness\" "
         "0.05\n"
         "  ActiveTransform EndTime\n  Translate 0.5 0 0\n  ActiveTransform All\n"
         "  Translate 0 0.5 0\n  Shape \"sphere\" \"float radius\" 0.5\n"
         "AttributeEnd\n";
  SceneDesc s = load_pbrt_scene(dir / "s.pbrt", false).scene;
  write_scene_json(s, dir / "s.json");
  EXPECT_TRUE(fs::exists(dir / "s.meshes" / "shape0.obj"));
  SceneDesc back = load_scene(dir / "s.json");
  EXPECT_EQ(back.integrator.environment_sampling, EnvironmentSampling::Compensated);  // pbrt-v4's rule kept
  EXPECT_LT(image_difference(s, back), 1e-3);
  fs::remove_all(dir);
}

// pbrt-v4's layered materials (coated_diffuse "model": "layered", coated_conductor) keep every
// parameter of their slab through `pdrt convert`, and the image.
TEST(SceneWriter, LayeredMaterialsRoundTripWithTheirSlab) {
  const fs::path dir = temp_dir();
  std::ofstream(dir / "s.pbrt")
      << "LookAt 0 2 -5  0 0.5 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" 40\n"
         "WorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n"
         "Material \"coateddiffuse\" \"rgb reflectance\" [0.6 0.3 0.2] \"float roughness\" 0.15 \"float thickness\" 0.3"
         " \"rgb albedo\" [0.4 0.5 0.6] \"float g\" 0.2 \"integer maxdepth\" 6 \"integer nsamples\" 2 \"float eta\" "
         "1.33\n"
         "Shape \"sphere\" \"float radius\" 0.8\n"
         "Material \"coatedconductor\" \"float interface.roughness\" 0.05 \"float conductor.roughness\" 0.3"
         " \"spectrum conductor.eta\" \"metal-Au-eta\" \"spectrum conductor.k\" \"metal-Au-k\"\n"
         "Translate 1.5 0 0\nShape \"sphere\" \"float radius\" 0.5\n";
  SceneDesc s = load_pbrt_scene(dir / "s.pbrt", false).scene;
  write_scene_json(s, dir / "s.json");
  SceneDesc back = load_scene(dir / "s.json");
  ASSERT_EQ(back.materials.size(), s.materials.size());
  for (size_t i = 0; i < s.materials.size(); ++i) {
    const Material &a = s.materials[i], &b = back.materials[i];
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.layered, b.layered);
    EXPECT_EQ(a.roughness, b.roughness);
    EXPECT_EQ(a.base_roughness, b.base_roughness);
    EXPECT_EQ(a.ior, b.ior);
    EXPECT_EQ(a.layers.thickness, b.layers.thickness);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(a.layers.albedo[c], b.layers.albedo[c]);
    EXPECT_EQ(a.layers.g, b.layers.g);
    EXPECT_EQ(a.layers.max_depth, b.layers.max_depth);
    EXPECT_EQ(a.layers.samples, b.layers.samples);
  }
  EXPECT_LT(image_difference(s, back), 1e-6);
  fs::remove_all(dir);
}

// Prototypes and instances (static and moving) written as "prototypes" and instance objects:
// each prototype mesh once, however many instances place it.
TEST(SceneWriter, PrototypesAndInstancesRoundTripWithEachMeshWrittenOnce) {
  const fs::path dir = temp_dir();
  std::ofstream(dir / "s.pbrt")
      << "LookAt 0 2 -6  0 0.5 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" 40\n"
         "WorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n"
         "ObjectBegin \"tile\"\n"
         "  Rotate 20 0 1 0\n"
         "  Shape \"trianglemesh\" \"point3 P\" [-1 0 -1 1 0 -1 1 0 1 -1 0 1] \"integer indices\" [0 1 2 0 2 3]\n"
         "  Translate 0 0.4 0\n"
         "  Shape \"sphere\" \"float radius\" 0.4\n"
         "ObjectEnd\n"
         "AttributeBegin\n  Translate -1.2 0 0\n  ObjectInstance \"tile\"\nAttributeEnd\n"
         "AttributeBegin\n  Translate 1.2 0 0\n  Scale 0.8 0.8 0.8\n  ObjectInstance \"tile\"\nAttributeEnd\n"
         "AttributeBegin\n  ActiveTransform EndTime\n  Translate 0.4 0 0\n  ActiveTransform All\n"
         "  Translate 0 0 2\n  ObjectInstance \"tile\"\nAttributeEnd\n";
  SceneDesc s = load_pbrt_scene(dir / "s.pbrt", false).scene;
  ASSERT_EQ(s.instances.size(), 3u);
  write_scene_json(s, dir / "s.json");
  std::size_t meshes = 0;
  for (const auto& e : fs::directory_iterator(dir / "s.meshes")) meshes += e.path().extension() == ".obj";
  EXPECT_EQ(meshes, 1u);  // the tile, once
  SceneDesc back = load_scene(dir / "s.json");
  ASSERT_EQ(back.prototypes.size(), 1u);
  EXPECT_EQ(back.prototypes[0].shapes.size(), 2u);
  ASSERT_EQ(back.instances.size(), 3u);
  EXPECT_EQ(back.instances[2].motion.size(), 2u);
  EXPECT_TRUE(back.shapes.empty());
  EXPECT_LT(image_difference(s, back), 1e-3);
  fs::remove_all(dir);
}

// The materials and textures of issue 18's second part: a mix (of a thin dielectric and a
// conductor of textured reflectance and roughness), scale, mix, invert and power textures.
TEST(SceneWriter, MixThinDielectricAndCombinedTexturesRoundTripToTheSameImage) {
  const fs::path dir = temp_dir();
  std::ofstream(dir / "s.pbrt")
      << "LookAt 0 2 -5  0 0.5 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" 40\n"
         "WorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.55]\n"
         "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 8 \"float vscale\" 8\n"
         "Texture \"half\" \"spectrum\" \"scale\" \"texture tex\" \"checks\" \"float scale\" 0.5\n"
         "Texture \"f0\" \"spectrum\" \"mix\" \"texture tex1\" \"half\" \"rgb tex2\" [0.9 0.6 0.2] \"float amount\" "
         "0.25\n"
         "Texture \"r\" \"float\" \"checkerboard\" \"float tex1\" 0.01 \"float tex2\" 0.2 \"float uscale\" 4\n"
         "MakeNamedMaterial \"sheet\" \"string type\" \"thindielectric\" \"float eta\" 1.4\n"
         "MakeNamedMaterial \"metal\" \"string type\" \"conductor\" \"texture reflectance\" \"f0\" \"texture "
         "roughness\" \"r\"\n"
         "MakeNamedMaterial \"paint\" \"string type\" \"diffuse\" \"texture reflectance\" \"checks\"\n"
         "MakeNamedMaterial \"inner\" \"string type\" \"mix\" \"string materials\" [\"sheet\" \"metal\"] \"float "
         "amount\" 0.6\n"
         "Material \"mix\" \"string materials\" [\"paint\" \"inner\"] \"texture amount\" \"r\"\n"
         "Shape \"trianglemesh\" \"point3 P\" [-3 0 -3 3 0 -3 3 0 3 -3 0 3] \"integer indices\" [0 1 2 0 2 3]"
         " \"point2 uv\" [0 0 1 0 1 1 0 1]\n"
         "NamedMaterial \"inner\"\n"
         "Translate 0 0.5 0\nShape \"sphere\" \"float radius\" 0.5\n";
  SceneDesc s = load_pbrt_scene(dir / "s.pbrt", false).scene;
  write_scene_json(s, dir / "s.json");
  SceneDesc back = load_scene(dir / "s.json");
  ASSERT_EQ(back.materials.size(), s.materials.size());
  ASSERT_EQ(back.textures.size(), s.textures.size());
  int mixes = 0, thin = 0;
  for (const Material& m : back.materials)
    mixes += m.type == MaterialType::Mix, thin += m.type == MaterialType::ThinDielectric;
  EXPECT_EQ(mixes, 2);
  EXPECT_EQ(thin, 1);
  EXPECT_LT(image_difference(s, back), 1e-3);
  fs::remove_all(dir);
}

TEST(SceneWriter, ConvertRefusesAnOutputThatIsNotJson) {
  const fs::path dir = temp_dir();
  CliResult r = run_pdrt("convert '" + (fs::path(PDRT_EXAMPLES_DIR) / "all-features.json").string() + "' -o '" +
                         (dir / "x.obj").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--out: the converted scene is JSON"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.obj"));
  fs::remove_all(dir);
}
