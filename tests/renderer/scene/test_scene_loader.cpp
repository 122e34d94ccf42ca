// Scene loading (renderer/scene_loader.h): the example scene's values, and for bad input,
// that the message names file:line:col and the JSON path. Expected positions are counted by
// hand from the scene text in each test (lines from 1 at the opening brace, columns from 1).
#include "sampling/core/errors.h"
#include "renderer/image/image_module.h"
#include "renderer/scene/json_locations.h"
#include "renderer/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace pdrt;

namespace {

const fs::path kData = fs::path(PDRT_TEST_DATA_DIR) / "scenes";
const fs::path kExamples = PDRT_EXAMPLES_DIR;
const fs::path kDocs = PDRT_DOCS_DIR;
const fs::path kScenes = PDRT_SCENES_DIR;

// A fresh directory per test and process (the ASan and plain suites may run side by side).
fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir =
      fs::temp_directory_path() / ("pdrt_scene_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path write(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

// Writes s.json (and copies the named fixtures beside it).
fs::path scene(const std::string& text, std::initializer_list<const char*> fixtures = {}) {
  fs::path dir = temp_dir();
  for (const char* f : fixtures) fs::copy_file(kData / f, dir / f);
  return write(dir / "s.json", text);
}

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string load_error(const fs::path& file) {
  try {
    load_scene(file);
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "messages are one line: " << m;
    return m;
  }
  ADD_FAILURE() << "expected an InputError for " << file;
  return "";
}

#define EXPECT_ERROR(file, text) EXPECT_NE(load_error(file).find(text), std::string::npos) << load_error(file)

void expect_vec(const Vec3& v, float x, float y, float z) {
  EXPECT_FLOAT_EQ(v.x, x);
  EXPECT_FLOAT_EQ(v.y, y);
  EXPECT_FLOAT_EQ(v.z, z);
}

// A valid camera and film on lines 2 and 3, for tests about the other sections.
const std::string kHead =
    "{\n"
    "  \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
    "  \"film\": {\"width\": 8, \"height\": 8},\n";

const Material& material_of(const SceneDesc& s, const ShapeDesc& shape) { return s.materials.at(shape.material); }

}  // namespace

// Removes the test's temporary directory afterwards.
class SceneLoader : public ::testing::Test {
 protected:
  void TearDown() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::error_code ec;
    fs::remove_all(
        fs::temp_directory_path() / ("pdrt_scene_" + std::string(info->name()) + "_" + std::to_string(::getpid())), ec);
  }
};

// --- the example scene (docs/scene-format.md) ---------------------------------------------

TEST_F(SceneLoader, ExampleCameraValues) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  EXPECT_EQ(s.file, kExamples / "all-features.json");
  expect_vec(s.camera.position, 0, 1, 6);
  EXPECT_FLOAT_EQ(s.camera.vfov_deg, 35);
  EXPECT_FLOAT_EQ(s.camera.aperture_radius, 0.05f);
  EXPECT_FLOAT_EQ(s.camera.focus_distance, 6);
  EXPECT_EQ(s.camera.aperture_blades, 6);
  EXPECT_FLOAT_EQ(s.camera.aperture_rotation_deg, 15);
  ASSERT_EQ(s.camera.motion.size(), 2u);
  EXPECT_FLOAT_EQ(s.camera.motion[1].time, 1);
  expect_vec(s.camera.motion[1].position, 0.5f, 1, 6);
}

TEST_F(SceneLoader, ExampleFilmSamplerIntegratorValues) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  EXPECT_EQ(s.film.width, 320);
  EXPECT_EQ(s.film.height, 240);
  EXPECT_EQ(s.film.filter.type, FilterType::Mitchell);
  EXPECT_EQ(s.film.filter.reconstruction, Reconstruction::Rank);
  EXPECT_FLOAT_EQ(s.film.exposure, 0.5f);
  EXPECT_EQ(s.sampler.type, "poisson");
  EXPECT_EQ(s.sampler.spp, 32);
  EXPECT_EQ(s.sampler.seed, 7u);
  EXPECT_TRUE(s.sampler.adaptive.enabled);
  EXPECT_EQ(s.sampler.adaptive.max_spp, 128);
  EXPECT_EQ(s.sampler.adaptive.metric, AdaptiveMetricKind::Contrast);
  EXPECT_EQ(s.sampler.adaptive.variance, AdaptiveVariance::Halves);
  EXPECT_EQ(s.integrator.max_depth, 6);
  EXPECT_EQ(s.integrator.rr_depth, 2);
}

TEST_F(SceneLoader, ExampleShapesMaterialsAndLights) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  // quad, sphere, mesh, 4 tetrahedron faces (one per MTL material), 1 overridden tetrahedron,
  // 3 spheres, then the quad and sphere lights.
  ASSERT_EQ(s.shapes.size(), 13u);
  EXPECT_EQ(material_of(s, s.shapes[0]).name, "white");
  EXPECT_EQ(s.shapes[1].kind, ShapeDesc::Kind::Sphere);
  EXPECT_EQ(material_of(s, s.shapes[2]).lobe, GlossLobe::Phong);
  EXPECT_EQ(s.shapes[2].mesh.normals.size(), 3u);
  EXPECT_EQ(material_of(s, s.shapes[7]).name, "chrome");
  EXPECT_EQ(s.shapes[7].mesh.indices.size(), 12u);
  EXPECT_EQ(material_of(s, s.shapes[10]).type, MaterialType::Mix);
  const ShapeDesc& light = s.shapes[11];
  EXPECT_EQ(material_of(s, light).name, "lights[0]");
  EXPECT_EQ(material_of(s, light).type, MaterialType::Emitter);
  expect_vec(material_of(s, light).radiance, 10, 10, 10);
  // The generated sky (found in the build's assets), dimmed and turned.
  EXPECT_EQ(s.environment.width, 512);
  EXPECT_EQ(fs::path(s.environment.file).filename(), "sky.exr");
  expect_vec(s.environment.scale, 0.1f, 0.1f, 0.12f);
  EXPECT_FLOAT_EQ(s.environment.rotation_deg, 30);
  EXPECT_EQ(s.shapes[12].where, (kExamples / "all-features.json").string() + ": lights[1]");
  EXPECT_EQ(s.degenerate_triangles, 0);
}

TEST_F(SceneLoader, ExampleDeltaLights) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  ASSERT_EQ(s.delta_lights.size(), 4u);
  const DeltaLightDesc& point = s.delta_lights[0];
  EXPECT_EQ(point.kind, DeltaLightDesc::Kind::Point);
  expect_vec(point.position, -2, 2, 1);
  expect_vec(point.intensity, 2, 1.8f, 1.5f);
  ASSERT_EQ(point.motion.size(), 2u);
  expect_vec(point.motion[1].translate, 0.2f, 0, 0);
  const DeltaLightDesc& spot = s.delta_lights[1];
  EXPECT_EQ(spot.kind, DeltaLightDesc::Kind::Spot);
  const Vec3 axis = normalize(Vec3(-0.5f, -2.6f, -0.5f));  // look_at - position, in object space
  expect_vec(spot.direction, axis.x, axis.y, axis.z);
  EXPECT_FLOAT_EQ(spot.cos_cone, std::cos(25 * float(M_PI) / 180));
  EXPECT_FLOAT_EQ(spot.cos_falloff_start, std::cos(15 * float(M_PI) / 180));
  expect_vec(spot.transform.point(spot.position), 2, 3.5f, 2);
  // Defaults: cone 30 degrees, falloff from 25.
  EXPECT_FLOAT_EQ(s.delta_lights[2].cos_cone, std::cos(30 * float(M_PI) / 180));
  EXPECT_FLOAT_EQ(s.delta_lights[2].cos_falloff_start, std::cos(25 * float(M_PI) / 180));
  const DeltaLightDesc& sun = s.delta_lights[3];
  EXPECT_EQ(sun.kind, DeltaLightDesc::Kind::Distant);
  const Vec3 travel = normalize(Vec3(-1, -2, -1));
  expect_vec(sun.direction, travel.x, travel.y, travel.z);
  expect_vec(sun.irradiance, 0.5f, 0.5f, 0.45f);
}

TEST_F(SceneLoader, ExampleMtlMapping) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  auto find = [&](const std::string& name) -> const Material& {
    for (const Material& m : s.materials)
      if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return s.materials.at(0);
  };
  const Material& clay = find("tetrahedron/clay");
  EXPECT_EQ(clay.type, MaterialType::Diffuse);
  expect_vec(clay.albedo, 0.7f, 0.4f, 0.3f);
  const Material& gold = find("tetrahedron/gold");
  EXPECT_EQ(gold.type, MaterialType::Glossy);
  EXPECT_EQ(gold.lobe, GlossLobe::Phong);
  EXPECT_FLOAT_EQ(gold.exponent, 200);
  expect_vec(gold.albedo, 0.9f, 0.7f, 0.3f);
  const Material& glass = find("tetrahedron/glass");
  EXPECT_EQ(glass.type, MaterialType::Dielectric);
  EXPECT_FLOAT_EQ(glass.ior, 1.33f);
  const Material& lamp = find("tetrahedron/lamp");
  EXPECT_EQ(lamp.type, MaterialType::Emitter);
  expect_vec(lamp.radiance, 4, 4, 3);
  // One shape per material; each tetrahedron face becomes a one-triangle mesh.
  for (int i = 3; i < 7; ++i) EXPECT_EQ(s.shapes[i].mesh.indices.size(), 3u);
}

TEST_F(SceneLoader, ExampleTransforms) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  // Sphere: translate [-1.5, 0.5, 0] * rotate x 30 * rotate y 90 (first listed innermost).
  Affine expected = Affine::translate({-1.5f, 0.5f, 0}) * Affine::rotate({1, 0, 0}, 30) * Affine::rotate({0, 1, 0}, 90);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(s.shapes[1].transform.m[r][c], expected.m[r][c], 1e-6f);
  // Tetrahedron: translate [0, 0, 1] * scale 0.8.
  expect_vec(s.shapes[3].transform.point({1, 1, 1}), 0.8f, 0.8f, 1.8f);
  // Matrix transform (3x4 row-major).
  expect_vec(s.shapes[7].transform.point({0, 0, 0}), 2.5f, 0, 0);
}

TEST_F(SceneLoader, ExampleMotionKeys) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  const auto& m = s.shapes[1].motion;
  ASSERT_EQ(m.size(), 3u);
  EXPECT_FLOAT_EQ(m[1].time, 0.5f);
  expect_vec(m[1].translate, 0, 0.25f, 0);
  expect_vec(m[2].scale, 1.2f, 1.2f, 1.2f);
  Quat q = Quat::from_axis_angle({0, 0, 1}, 45);
  EXPECT_FLOAT_EQ(m[2].rotate.w, q.w);
  EXPECT_FLOAT_EQ(m[2].rotate.z, q.z);
  expect_vec(m[0].scale, 1, 1, 1);  // keys default to identity
  ASSERT_EQ(s.shapes[12].motion.size(), 2u);
}

TEST_F(SceneLoader, DocumentedExampleMatchesTheExampleFile) {
  std::string doc = read(kDocs / "scene-format.md");
  const std::string fence = "```json\n";
  size_t begin = doc.rfind(fence);
  ASSERT_NE(begin, std::string::npos);
  begin += fence.size();
  size_t end = doc.find("```", begin);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(doc.substr(begin, end - begin), read(kExamples / "all-features.json"));
}

TEST_F(SceneLoader, EverySceneInTheRepositoryLoads) {
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kScenes)) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    EXPECT_NO_THROW(load_scene(entry.path())) << entry.path();
  }
  EXPECT_GT(count, 0);
}

// --- defaults and geometry ----------------------------------------------------------------

TEST_F(SceneLoader, DefaultsFilledIn) {
  SceneDesc s = load_scene(scene(kHead + "  \"objects\": []\n}\n"));
  expect_vec(s.camera.up, 0, 1, 0);
  EXPECT_FLOAT_EQ(s.camera.vfov_deg, 40);
  EXPECT_FLOAT_EQ(s.camera.focus_distance, 5);  // resolved from |look_at - position|
  EXPECT_FLOAT_EQ(s.camera.shutter_open, 0);
  EXPECT_FLOAT_EQ(s.camera.shutter_close, 1);
  EXPECT_EQ(s.film.filter.type, FilterType::Gaussian);
  EXPECT_FLOAT_EQ(s.film.filter.radius, 1.5f);
  EXPECT_EQ(s.film.filter.reconstruction, Reconstruction::Importance);
  EXPECT_EQ(s.sampler.type, "poisson");
  EXPECT_EQ(s.sampler.spp, 16);
  EXPECT_FALSE(s.sampler.adaptive.enabled);
  EXPECT_EQ(s.integrator.max_depth, 8);
  EXPECT_EQ(s.integrator.rr_depth, 3);
}

// Path regularisation is biased: a scene gets it only by asking.
TEST_F(SceneLoader, RegularizeIsOffUnlessTheSceneAsks) {
  EXPECT_FALSE(load_scene(scene(kHead + "  \"integrator\": {\"max_depth\": 4}\n}\n")).integrator.regularize);
  EXPECT_TRUE(load_scene(scene(kHead + "  \"integrator\": {\"regularize\": true}\n}\n")).integrator.regularize);
}

TEST_F(SceneLoader, RegularizeMustBeABoolean) {
  fs::path f = scene(kHead + "  \"integrator\": {\"regularize\": 1}\n}\n");
  EXPECT_ERROR(f, "s.json:4:32: integrator.regularize must be true or false, got 1");
}

// pbrt-v4's environment sampling (MIS compensation) is a scene's choice; pdrt's default is
// full sampling, and an unknown name is refused at its position.
TEST_F(SceneLoader, EnvironmentSamplingIsFullUnlessTheSceneSaysCompensated) {
  EXPECT_EQ(load_scene(scene(kHead + "  \"integrator\": {\"max_depth\": 4}\n}\n")).integrator.environment_sampling,
            EnvironmentSampling::Full);
  EXPECT_EQ(load_scene(scene(kHead + "  \"integrator\": {\"environment_sampling\": \"compensated\"}\n}\n"))
                .integrator.environment_sampling,
            EnvironmentSampling::Compensated);
  fs::path f = scene(kHead + "  \"integrator\": {\"environment_sampling\": \"incomplete\"}\n}\n");
  EXPECT_ERROR(f, "s.json:4:42: integrator.environment_sampling must be one of full, compensated, got \"incomplete\"");
}

TEST_F(SceneLoader, FilterRadiusDefaultDependsOnType) {
  SceneDesc s =
      load_scene(scene("{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},"
                       " \"film\": {\"width\": 8, \"height\": 8, \"filter\": {\"type\": \"box\"}}}"));
  EXPECT_EQ(s.film.filter.type, FilterType::Box);
  EXPECT_FLOAT_EQ(s.film.filter.radius, 0.5f);
}

TEST_F(SceneLoader, GaussianSigmaSelectsPbrtsSeparableGaussianAndOnlyForGaussians) {
  SceneDesc s = load_scene(
      scene("{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},"
            " \"film\": {\"width\": 8, \"height\": 8, \"filter\": {\"type\": \"gaussian\", \"sigma\": 0.5}}}"));
  EXPECT_FLOAT_EQ(s.film.filter.sigma, 0.5f);
  EXPECT_ERROR(scene("{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},"
                     " \"film\": {\"width\": 8, \"height\": 8, \"filter\": {\"type\": \"box\", \"sigma\": 0.5}}}"),
               "film.filter.sigma is a parameter of the \"gaussian\" filter only, not of \"box\"");
  EXPECT_ERROR(scene("{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},"
                     " \"film\": {\"width\": 8, \"height\": 8, \"filter\": {\"sigma\": -1}}}"),
               "film.filter.sigma");
}

TEST_F(SceneLoader, MaterialTypeDefaults) {
  SceneDesc s = load_scene(scene(kHead + R"(  "materials": {
    "d": {"type": "diffuse"}, "g": {"type": "glossy", "roughness": 0.5},
    "m": {"type": "mirror"}, "t": {"type": "dielectric"}
  }
})"));
  ASSERT_EQ(s.materials.size(), 4u);  // sorted by name: d, g, m, t
  expect_vec(s.materials[0].albedo, 0.8f, 0.8f, 0.8f);
  expect_vec(s.materials[1].albedo, 0.9f, 0.9f, 0.9f);
  EXPECT_EQ(s.materials[1].lobe, GlossLobe::GGX);
  expect_vec(s.materials[2].albedo, 1, 1, 1);
  EXPECT_FLOAT_EQ(s.materials[3].ior, 1.5f);
  EXPECT_FLOAT_EQ(s.materials[3].roughness, 0);
}

TEST_F(SceneLoader, AdaptiveDefaultsLeaveTheThresholdToTheMetric) {
  SceneDesc s = load_scene(scene(kHead + "  \"sampler\": {\"adaptive\": {\"metric\": \"contrast\"}}\n}\n"));
  EXPECT_TRUE(s.sampler.adaptive.enabled);
  EXPECT_EQ(s.sampler.adaptive.threshold, 0) << "unset: the renderer uses the metric's default";
  EXPECT_EQ(s.sampler.adaptive.variance, AdaptiveVariance::Samples);
  SceneDesc d = load_scene(scene(kHead + "  \"sampler\": {\"adaptive\": {}}\n}\n"));
  EXPECT_EQ(d.sampler.adaptive.metric, AdaptiveMetricKind::ErrorPerSample);
}

TEST_F(SceneLoader, AdaptiveVarianceHalves) {
  SceneDesc s = load_scene(scene(kHead + "  \"sampler\": {\"adaptive\": {\"variance\": \"halves\"}}\n}\n"));
  EXPECT_EQ(s.sampler.adaptive.variance, AdaptiveVariance::Halves);
}

TEST_F(SceneLoader, UnknownAdaptiveVariance) {
  fs::path f = scene(kHead + "  \"sampler\": {\"adaptive\": {\"variance\": \"pixels\"}}\n}\n");
  EXPECT_ERROR(f, "s.json:4:40: sampler.adaptive.variance must be one of samples, halves, got \"pixels\"");
}

TEST_F(SceneLoader, AdaptiveDecisionSplit) {
  SceneDesc s = load_scene(scene(kHead + "  \"sampler\": {\"adaptive\": {\"decision\": \"split\"}}\n}\n"));
  EXPECT_EQ(s.sampler.adaptive.decision, AdaptiveDecision::Split);
  SceneDesc d = load_scene(scene(kHead + "  \"sampler\": {\"adaptive\": {}}\n}\n"));
  EXPECT_EQ(d.sampler.adaptive.decision, AdaptiveDecision::Shared);
}

TEST_F(SceneLoader, UnknownAdaptiveDecision) {
  fs::path f = scene(kHead + "  \"sampler\": {\"adaptive\": {\"decision\": \"halves\"}}\n}\n");
  EXPECT_ERROR(f, "s.json:4:40: sampler.adaptive.decision must be one of shared, split, got \"halves\"");
}

std::string film_with_filter(const std::string& filter) {
  return "{\n  \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
         "  \"film\": {\"width\": 8, \"height\": 8, \"filter\": " +
         filter + "}";
}

TEST_F(SceneLoader, FilterReconstructionModes) {
  const std::pair<const char*, Reconstruction> modes[] = {
      {"importance", Reconstruction::Importance}, {"splat", Reconstruction::Splat}, {"rank", Reconstruction::Rank}};
  for (const auto& [name, mode] : modes) {
    SceneDesc s = load_scene(scene(film_with_filter(std::string("{\"reconstruction\": \"") + name + "\"}") + "\n}\n"));
    EXPECT_EQ(s.film.filter.reconstruction, mode) << name;
  }
}

TEST_F(SceneLoader, UnknownReconstruction) {
  fs::path f = scene(film_with_filter("{\"reconstruction\": \"weights\"}") + "\n}\n");
  EXPECT_ERROR(f, "s.json:3:66: film.filter.reconstruction must be one of importance, splat, rank, got \"weights\"");
}

TEST_F(SceneLoader, OldSelectionKeyNamesItsReplacement) {
  fs::path f = scene(film_with_filter("{\"selection\": \"rank\"}") + "\n}\n");
  EXPECT_ERROR(f,
               "s.json:3:48: film.filter.selection was replaced by \"reconstruction\": \"importance\" (default), "
               "\"splat\" or \"rank\"");
}

TEST_F(SceneLoader, SplitDecisionWithRankReconstructionIsRefused) {
  fs::path f = scene(film_with_filter("{\"reconstruction\": \"rank\"}") +
                     ",\n  \"sampler\": {\"adaptive\": {\"decision\": \"split\"}}\n}\n");
  EXPECT_ERROR(f,
               "s.json:4:40: sampler.adaptive.decision \"split\" needs reconstruction \"importance\" or "
               "\"splat\", not \"rank\"");
}

TEST_F(SceneLoader, QuadIsTwoCounterClockwiseTriangles) {
  SceneDesc s = load_scene(scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "quad", "material": "grey", "corner": [1, 2, 3], "edge1": [2, 0, 0], "edge2": [0, 3, 0]}]
})"));
  const MeshData& m = s.shapes.at(0).mesh;
  ASSERT_EQ(m.positions.size(), 4u);
  expect_vec(m.positions[2], 3, 5, 3);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  for (int t = 0; t < 2; ++t) {  // both face along cross(edge1, edge2) = +z
    const Vec3 &a = m.positions[m.indices[3 * t]], &b = m.positions[m.indices[3 * t + 1]],
               &c = m.positions[m.indices[3 * t + 2]];
    EXPECT_GT(cross(b - a, c - a).z, 0);
  }
}

TEST_F(SceneLoader, SixteenNumberMatrixAccepted) {
  SceneDesc s = load_scene(scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1,
               "transform": {"matrix": [2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]}}]
})"));
  expect_vec(s.shapes.at(0).transform.point({1, 1, 1}), 3, 2, 2);
}

TEST_F(SceneLoader, DegenerateTrianglesCountedNotError) {
  fs::path file = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [
    {"type": "mesh", "material": "grey", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 0, 0]],
     "indices": [0, 1, 2, 0, 0, 1, 0, 1, 3]},
    {"type": "obj", "file": "degenerate.obj"}
  ]
})",
                        {"degenerate.obj"});
  ::testing::internal::CaptureStderr();
  SceneDesc s = load_scene(file);
  std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(s.degenerate_triangles, 2 + 3);
  EXPECT_EQ(s.shapes.at(0).mesh.indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(s.shapes.at(1).mesh.indices.size(), 3u);
  EXPECT_EQ(err, file.string() + ": warning: skipped 5 degenerate triangles\n");
}

// --- bad input: JSON ----------------------------------------------------------------------

TEST_F(SceneLoader, SyntaxErrorHasLineAndColumn) {
  // Line 3: the '}' after the trailing comma is column 36.
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "film": {"width": 8, "height": 8,}
})");
  EXPECT_ERROR(f, "s.json:3:36: JSON syntax error");
}

TEST_F(SceneLoader, SyntaxErrorAtEndOfInput) {
  fs::path f = scene("{\n  \"camera\": {\n");
  EXPECT_ERROR(f, "s.json:3:1: JSON syntax error");
}

TEST_F(SceneLoader, UnknownTopLevelKey) {
  fs::path f = scene(kHead + "  \"lights\": [],\n  \"light\": []\n}\n");
  EXPECT_ERROR(f, "s.json:5:3: light unknown key (did you mean \"lights\"?)");
}

TEST_F(SceneLoader, UnknownNestedKeySuggestsNearest) {
  fs::path f = scene(R"({
  "camera": {
    "position": [0, 0, 5],
    "look_at": [0, 0, 0],
    "fov_deg": 30
  },
  "film": {"width": 8, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:5:5: camera.fov_deg unknown key (did you mean \"vfov_deg\"?)");
}

TEST_F(SceneLoader, UnknownKeyInsideObjectArray) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1, "colour": 3}]
})");
  EXPECT_ERROR(f, "s.json:5:67: objects[0].colour unknown key (expected one of:");
}

TEST_F(SceneLoader, WrongType) {
  fs::path f = scene(R"({
  "camera": {"position": "origin", "look_at": [0, 0, 0]},
  "film": {"width": 8, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:2:26: camera.position must be an array of 3 numbers, got \"origin\"");
}

TEST_F(SceneLoader, MissingRequiredKey) {
  fs::path f = scene(R"({
  "camera": {"look_at": [0, 0, 0]},
  "film": {"width": 8, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:2:13: camera missing required key \"position\"");
}

TEST_F(SceneLoader, MissingRequiredTopLevelKey) {
  fs::path f = scene("{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]}}");
  EXPECT_ERROR(f, "s.json:1:1: missing required key \"film\"");
}

TEST_F(SceneLoader, InfiniteNumberRejected) {
  // nlohmann reads 1e999 as inf; the message shows the number as written.
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "vfov_deg": 1e999},
  "film": {"width": 8, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:2:71: camera.vfov_deg must be a finite number, got 1e999");
}

TEST_F(SceneLoader, NegativeRadius) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [
    {"type": "sphere", "material": "grey", "radius": 1},
    {"type": "sphere", "material": "grey",
     "radius": -1}
  ]
})");
  EXPECT_ERROR(f, "s.json:8:16: objects[1].radius must be > 0, got -1");
}

TEST_F(SceneLoader, ZeroResolution) {
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "film": {"width": 0, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:3:21: film.width must be an integer in [1, 65536], got 0");
}

TEST_F(SceneLoader, NegativeResolution) {
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "film": {"width": 8, "height": -4}
})");
  EXPECT_ERROR(f, "s.json:3:34: film.height must be an integer in [1, 65536], got -4");
}

TEST_F(SceneLoader, FractionalResolution) {
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "film": {"width": 8.5, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:3:21: film.width must be an integer in [1, 65536], got 8.5");
}

TEST_F(SceneLoader, ZeroLengthUpVector) {
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0],
             "up": [0, 0, 0]},
  "film": {"width": 8, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:3:20: camera.up must be non-zero, got [0,0,0]");
}

TEST_F(SceneLoader, UpParallelToViewDirection) {
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0],
             "up": [0, 0, 2]},
  "film": {"width": 8, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:3:20: camera.up must not be parallel to look_at - position");
}

TEST_F(SceneLoader, UnknownMaterialName) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "radius": 1, "material": "gold"}]
})");
  EXPECT_ERROR(f, "s.json:5:59: objects[0].material unknown material \"gold\"");
}

TEST_F(SceneLoader, DuplicateKeyRejected) {
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]},
  "film": {"width": 8, "height": 8, "width": 16}
})");
  EXPECT_ERROR(f, "s.json:3:37: film.width duplicate key");
}

TEST_F(SceneLoader, MotionTimeOutsideShutter) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1,
               "motion": [{"time": 0}, {"time": 1.5}]}]
})");
  EXPECT_ERROR(f, "s.json:6:49: objects[0].motion[1].time must be within the shutter [0, 1], got 1.5");
}

TEST_F(SceneLoader, MotionTimesNotIncreasing) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1,
               "motion": [{"time": 0.5}, {"time": 0.5}]}]
})");
  EXPECT_ERROR(f, "s.json:6:51: objects[0].motion[1].time must be greater than the previous key's time (0.5), got 0.5");
}

// A moving sphere keeps a sphere: Embree would scale its instance into an ellipsoid while
// light sampling samples a sphere, so a non-uniform key scale is refused (lights and objects).
TEST_F(SceneLoader, MovingSphereLightRefusesNonUniformScale) {
  fs::path f = scene(kHead + R"(  "lights": [{"type": "sphere", "radius": 0.5, "radiance": [1, 1, 1],
              "motion": [{"time": 0}, {"time": 1, "scale": [1, 2, 1]}]}]
})");
  EXPECT_ERROR(f,
               "s.json:5:60: lights[0].motion[1].scale must be uniform for a sphere (one number); use a mesh for an "
               "ellipsoid, got [1,2,1]");
}

TEST_F(SceneLoader, MovingSphereObjectAcceptsUniformScaleOnly) {
  fs::path ok = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1,
               "motion": [{"time": 0, "scale": 2}, {"time": 1, "scale": [3, 3, 3]}]}]
})");
  EXPECT_FLOAT_EQ(load_scene(ok).shapes[0].motion[1].scale.y, 3);
  fs::path bad = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1,
               "motion": [{"time": 0, "scale": [1, 1, 0.5]}, {"time": 1}]}]
})");
  EXPECT_ERROR(bad,
               "s.json:6:48: objects[0].motion[0].scale must be uniform for a sphere (one number); use a mesh for an "
               "ellipsoid, got [1,1,0.5]");
}

TEST_F(SceneLoader, CameraMotionOutsideShutter) {
  fs::path f = scene(R"({
  "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "shutter": [0, 0.5],
             "motion": [{"time": 0, "position": [0, 0, 5], "look_at": [0, 0, 0]},
                        {"time": 1, "position": [1, 0, 5], "look_at": [0, 0, 0]}]},
  "film": {"width": 8, "height": 8}
})");
  EXPECT_ERROR(f, "s.json:4:34: camera.motion[1].time must be within the shutter [0, 0.5], got 1");
}

TEST_F(SceneLoader, GlossyWithRoughnessAndExponent) {
  fs::path f = scene(kHead + R"(  "materials": {
    "shiny": {"type": "glossy", "roughness": 0.2, "exponent": 50}
  }
})");
  EXPECT_ERROR(f, "s.json:5:51: materials.shiny.exponent cannot be combined with roughness");
}

TEST_F(SceneLoader, EnergyCompensationDefaultsOnAndCanBeSwitchedOff) {
  SceneDesc s = load_scene(scene(kHead + R"(  "materials": {
    "a": {"type": "glossy", "roughness": 0.5}, "b": {"type": "glossy", "roughness": 0.5, "energy_compensation": false},
    "c": {"type": "dielectric", "roughness": 0.8}, "d": {"type": "dielectric", "roughness": 0.8, "energy_compensation": false}
  }
})"));
  ASSERT_EQ(s.materials.size(), 4u);
  EXPECT_TRUE(s.materials[0].energy_compensation);
  EXPECT_FALSE(s.materials[1].energy_compensation);
  EXPECT_TRUE(s.materials[2].energy_compensation);
  EXPECT_FALSE(s.materials[3].energy_compensation);
}

TEST_F(SceneLoader, EnergyCompensationMustBeABoolean) {
  fs::path f = scene(kHead + R"(  "materials": {
    "g": {"type": "glossy", "roughness": 0.5, "energy_compensation": 1}
  }
})");
  EXPECT_ERROR(f, "s.json:5:70: materials.g.energy_compensation must be");
}

TEST_F(SceneLoader, EnergyCompensationRefusedOnPhongAndDiffuse) {
  fs::path phong = scene(kHead + R"(  "materials": {
    "p": {"type": "glossy", "exponent": 20, "energy_compensation": true}
  }
})");
  EXPECT_ERROR(phong, "s.json:5:45: materials.p.energy_compensation applies to the GGX lobe (roughness) only");
  fs::path diffuse = scene(kHead + R"(  "materials": {
    "d": {"type": "diffuse", "energy_compensation": true}
  }
})");
  EXPECT_ERROR(diffuse, "s.json:5:30: materials.d");
  EXPECT_ERROR(diffuse, "energy_compensation");
}

TEST_F(SceneLoader, ConductorFromNamedMetalOrEtaAndK) {
  SceneDesc s = load_scene(scene(kHead + R"(  "materials": {
    "au": {"type": "conductor", "metal": "Au"},
    "cu": {"type": "conductor", "metal": "Cu", "roughness": 0.3, "energy_compensation": false},
    "own": {"type": "conductor", "eta": [0.2, 0.9, 1.1], "k": [3.9, 2.4, 0]}
  }
})"));
  ASSERT_EQ(s.materials.size(), 3u);
  const Material& au = s.materials[0];
  EXPECT_EQ(au.type, MaterialType::Conductor);
  EXPECT_FLOAT_EQ(au.roughness, 0);
  EXPECT_TRUE(au.energy_compensation);
  expect_vec(au.eta, find_named_metal("Au")->eta.x, find_named_metal("Au")->eta.y, find_named_metal("Au")->eta.z);
  expect_vec(au.k, find_named_metal("Au")->k.x, find_named_metal("Au")->k.y, find_named_metal("Au")->k.z);
  EXPECT_FLOAT_EQ(s.materials[1].roughness, 0.3f);
  EXPECT_FALSE(s.materials[1].energy_compensation);
  expect_vec(s.materials[2].eta, 0.2f, 0.9f, 1.1f);
  expect_vec(s.materials[2].k, 3.9f, 2.4f, 0);
  for (const char* name : {"Au", "Ag", "Cu", "Al"}) EXPECT_NE(find_named_metal(name), nullptr) << name;
}

TEST_F(SceneLoader, ConductorUnknownMetalListsTheKnownOnes) {
  fs::path f = scene(kHead + R"(  "materials": {
    "m": {"type": "conductor", "metal": "Pt"}
  }
})");
  EXPECT_ERROR(f, "s.json:5:41: materials.m.metal must be one of \"Ag\", \"Al\", \"Au\", \"Cu\", got \"Pt\"");
}

TEST_F(SceneLoader, ConductorMetalExcludesEtaAndK) {
  fs::path f = scene(kHead + R"(  "materials": {
    "m": {"type": "conductor", "metal": "Au", "k": [1, 1, 1]}
  }
})");
  EXPECT_ERROR(f, "s.json:5:47: materials.m.k cannot be combined with metal");
}

TEST_F(SceneLoader, ConductorNeedsMetalOrBothEtaAndK) {
  fs::path none = scene(kHead + R"(  "materials": {
    "m": {"type": "conductor", "roughness": 0.2}
  }
})");
  EXPECT_ERROR(none, "materials.m needs metal (one of \"Ag\", \"Al\", \"Au\", \"Cu\") or eta and k");
  fs::path no_k = scene(kHead + R"(  "materials": {
    "m": {"type": "conductor", "eta": [1, 1, 1]}
  }
})");
  EXPECT_ERROR(no_k, "s.json:5:10: materials.m");
  EXPECT_ERROR(no_k, "\"k\"");
}

TEST_F(SceneLoader, ConductorEtaAndKRanges) {
  auto with = [&](const std::string& eta, const std::string& k) {
    return scene(kHead + "  \"materials\": {\n    \"m\": {\"type\": \"conductor\", \"eta\": " + eta + ", \"k\": " + k +
                 "}\n  }\n}\n");
  };
  EXPECT_ERROR(with("[1, 0, 1]", "[1, 1, 1]"), "s.json:5:39: materials.m.eta must have finite components > 0");
  EXPECT_ERROR(with("[1, -1, 1]", "[1, 1, 1]"), "materials.m.eta must have finite components > 0");
  EXPECT_ERROR(with("[1, 1e39, 1]", "[1, 1, 1]"), "is too large for a float");
  EXPECT_ERROR(with("[1, 1, 1]", "[1, -0.5, 1]"), "s.json:5:55: materials.m.k must have finite components >= 0");
  EXPECT_ERROR(with("[1, 1, 1]", "[1, 1]"), "materials.m.k must be an array of 3 numbers");
  EXPECT_ERROR(with("[1, 1, 1]", "[1, 1, 1e39]"), "is too large for a float");
}

TEST_F(SceneLoader, ConductorRejectsAlbedoAndBadRoughness) {
  fs::path albedo = scene(kHead + R"(  "materials": {
    "m": {"type": "conductor", "metal": "Al", "albedo": [1, 1, 1]}
  }
})");
  EXPECT_ERROR(albedo, "materials.m");
  EXPECT_ERROR(albedo, "albedo");
  fs::path rough = scene(kHead + R"(  "materials": {
    "m": {"type": "conductor", "metal": "Al", "roughness": 1.5}
  }
})");
  EXPECT_ERROR(rough, "materials.m.roughness must be");
}

TEST_F(SceneLoader, CoatedDiffuseDefaultsAndEveryKey) {
  SceneDesc s = load_scene(scene(kHead + R"(  "materials": {
    "plain": {"type": "coated_diffuse"},
    "paint": {"type": "coated_diffuse", "albedo": [0.8, 0.1, 0.1], "roughness": 0.3, "ior": 1.33,
              "coat_color": [0.9, 0.8, 0.5], "coat_thickness": 2.5},
    "bare": {"type": "coated_diffuse", "ior": 1, "coat_thickness": 0}
  }
})"));
  ASSERT_EQ(s.materials.size(), 3u);
  auto find = [&](const std::string& name) -> const Material& {
    for (const Material& m : s.materials)
      if (m.name == name) return m;
    ADD_FAILURE() << "no material " << name;
    return s.materials.at(0);
  };
  const Material& plain = find("plain");
  EXPECT_EQ(plain.type, MaterialType::CoatedDiffuse);
  expect_vec(plain.albedo, 0.5f, 0.5f, 0.5f);
  EXPECT_FLOAT_EQ(plain.roughness, 0);
  EXPECT_FLOAT_EQ(plain.ior, 1.5f);
  expect_vec(plain.coat_color, 1, 1, 1);
  EXPECT_FLOAT_EQ(plain.coat_thickness, 1);
  const Material& paint = find("paint");
  EXPECT_EQ(paint.type, MaterialType::CoatedDiffuse);
  expect_vec(paint.albedo, 0.8f, 0.1f, 0.1f);
  EXPECT_FLOAT_EQ(paint.roughness, 0.3f);
  EXPECT_FLOAT_EQ(paint.ior, 1.33f);
  expect_vec(paint.coat_color, 0.9f, 0.8f, 0.5f);
  EXPECT_FLOAT_EQ(paint.coat_thickness, 2.5f);
  EXPECT_FLOAT_EQ(find("bare").ior, 1);
  EXPECT_FLOAT_EQ(find("bare").coat_thickness, 0);
}

TEST_F(SceneLoader, CoatedDiffuseRefusesBadValuesByName) {
  // Every material is on line 5: `    "m": {"type": "coated_diffuse", <keys>}`.
  auto with = [&](const std::string& keys) {
    return scene(kHead + "  \"materials\": {\n    \"m\": {\"type\": \"coated_diffuse\", " + keys + "}\n  }\n}\n");
  };
  EXPECT_ERROR(with(R"("ior": 0.5)"),
               "s.json:5:44: materials.m.ior must be in [1,3] (the coat's index relative to the outside), got 0.5");
  EXPECT_ERROR(with(R"("ior": 3.5)"), "s.json:5:44: materials.m.ior must be in [1,3]");
  EXPECT_ERROR(with(R"("ior": "glass")"), "s.json:5:44: materials.m.ior must be a number, got \"glass\"");
  EXPECT_ERROR(with(R"("coat_color": [1.2, 0, 0])"),
               "s.json:5:51: materials.m.coat_color must have components in [0,1], got [1.2,0,0]");
  EXPECT_ERROR(with(R"("coat_color": 0.5)"), "materials.m.coat_color must be an array of 3 numbers");
  EXPECT_ERROR(with(R"("coat_thickness": -1)"), "s.json:5:55: materials.m.coat_thickness must be >= 0, got -1");
  EXPECT_ERROR(with(R"("coat_thickness": 1e39)"), "is too large for a float");
  EXPECT_ERROR(with(R"("roughness": 1.5)"), "s.json:5:50: materials.m.roughness must be in [0,1], got 1.5");
  EXPECT_ERROR(with(R"("albedo": [0.5, 0.5, -0.1])"), "materials.m.albedo must have components in [0,1]");
}

TEST_F(SceneLoader, CoatedDiffuseRefusesOtherMaterialsKeys) {
  auto with = [&](const std::string& keys) {
    return scene(kHead + "  \"materials\": {\n    \"m\": {\"type\": \"coated_diffuse\", " + keys + "}\n  }\n}\n");
  };
  EXPECT_ERROR(with(R"("energy_compensation": true)"), "s.json:5:37: materials.m.energy_compensation unknown key");
  EXPECT_ERROR(with(R"("eta": [1, 1, 1])"), "materials.m.eta unknown key");
  EXPECT_ERROR(with(R"("thickness": 1)"),
               "materials.m.thickness unknown key (expected one of: type, model, albedo, roughness, ior, coat_color, "
               "coat_thickness)");
}

// pbrt-v4's layered model: its slab keys only with "model": "layered", the analytic coat's not then.
TEST_F(SceneLoader, LayeredCoatsTakeTheirSlabAndRefuseTheAnalyticKeys) {
  auto with = [&](const std::string& m) {
    return scene(kHead + "  \"materials\": {\n    \"m\": {" + m + "}\n  }\n}\n");
  };
  SceneDesc s = load_scene(
      with(R"("type": "coated_conductor", "metal": "Au", "ior": 1.2, "base_roughness": 0.3, )"
           R"("thickness": 0.5, "medium_albedo": [0.1, 0.2, 0.3], "g": -0.5, "max_depth": 4, "samples": 2)"));
  const Material& m = s.materials.at(0);
  EXPECT_EQ(m.type, MaterialType::CoatedConductor);
  EXPECT_FLOAT_EQ(m.ior, 1.2f);
  EXPECT_FLOAT_EQ(m.base_roughness, 0.3f);
  EXPECT_FLOAT_EQ(m.layers.thickness, 0.5f);
  EXPECT_FLOAT_EQ(m.layers.albedo.y, 0.2f);
  EXPECT_FLOAT_EQ(m.layers.g, -0.5f);
  EXPECT_EQ(m.layers.max_depth, 4);
  EXPECT_EQ(m.layers.samples, 2);
  EXPECT_ERROR(with(R"("type": "coated_diffuse", "model": "layered", "coat_color": [1, 1, 1])"),
               "s.json:5:57: materials.m.coat_color unknown key");
  EXPECT_ERROR(with(R"("type": "coated_diffuse", "model": "layered", "g": 1.5)"),
               "materials.m.g must be in [-1,1], got 1.5");
  EXPECT_ERROR(with(R"("type": "coated_diffuse", "model": "layered", "samples": 0)"), "materials.m.samples");
  EXPECT_ERROR(with(R"("type": "coated_diffuse", "model": "fancy")"), "materials.m.model must be one of");
  EXPECT_ERROR(with(R"("type": "coated_conductor", "ior": 1.5)"), "materials.m needs metal");
}

TEST_F(SceneLoader, AlbedoOutOfRange) {
  fs::path f = scene(kHead + R"(  "materials": {"hot": {"type": "diffuse", "albedo": [1.2, 0, 0]}}
})");
  EXPECT_ERROR(f, "s.json:4:54: materials.hot.albedo must have components in [0,1], got [1.2,0,0]");
}

TEST_F(SceneLoader, SingularMatrix) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1,
               "transform": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0]}}]
})");
  EXPECT_ERROR(f, "s.json:6:29: objects[0].transform is singular");
}

// Point, spot and distant lights: every rule refused at the offending value.
TEST_F(SceneLoader, DeltaLightsRefuseBadValuesByName) {
  auto lights = [](const std::string& text) { return scene(kHead + "  \"lights\": [" + text + "]\n}"); };
  // Every light is on line 4, after `  "lights": [`.
  EXPECT_ERROR(lights(R"({"type": "point", "intensity": [1, -1, 1]})"),
               "s.json:4:45: lights[0].intensity must have components >= 0, got [1,-1,1]");
  EXPECT_ERROR(lights(R"({"type": "point", "position": [0, 0, 0]})"),
               "s.json:4:14: lights[0] missing required key \"intensity\"");
  EXPECT_ERROR(lights(R"({"type": "point", "intensity": [1, 1, 1], "radiance": [1, 1, 1]})"),
               "s.json:4:56: lights[0].radiance unknown key");
  EXPECT_ERROR(lights(R"({"type": "distant", "direction": [0, 0, 0], "irradiance": [1, 1, 1]})"),
               "s.json:4:47: lights[0].direction must be non-zero, got [0,0,0]");
  EXPECT_ERROR(lights(R"({"type": "distant", "direction": [1e-30, 0, 0], "irradiance": [1, 1, 1]})"),
               "s.json:4:47: lights[0].direction is a direction that cannot be normalised in float");
  EXPECT_ERROR(
      lights(R"({"type": "distant", "direction": [0, -1, 0], "irradiance": [1, 1, 1], "position": [0, 1, 0]})"),
      "lights[0].position unknown key");
  const std::string spot = R"({"type": "spot", "intensity": [1, 1, 1], "direction": [0, -1, 0], )";
  EXPECT_ERROR(lights(spot + R"("cone_angle_deg": 0})"), "s.json:4:98: lights[0].cone_angle_deg must be in (0, 180]");
  EXPECT_ERROR(lights(spot + R"("cone_angle_deg": 180.5})"), "lights[0].cone_angle_deg must be in (0, 180]");
  EXPECT_ERROR(lights(spot + R"("cone_angle_deg": -10})"), "lights[0].cone_angle_deg must be in (0, 180]");
  EXPECT_ERROR(lights(spot + R"("cone_angle_deg": 20, "falloff_start_deg": 25})"),
               "lights[0].falloff_start_deg must be in [0, cone_angle_deg] = [0, 20], got 25");
  EXPECT_ERROR(lights(spot + R"("look_at": [0, 0, 0]})"), "lights[0].look_at cannot be combined with direction");
  EXPECT_ERROR(lights(R"({"type": "spot", "intensity": [1, 1, 1]})"),
               "s.json:4:14: lights[0] needs \"direction\" or \"look_at\"");
  EXPECT_ERROR(lights(R"({"type": "spot", "intensity": [1, 1, 1], "position": [1, 2, 3], "look_at": [1, 2, 3]})"),
               "lights[0].look_at must differ from the position");
  EXPECT_ERROR(lights(spot + R"("transform": {"translate": [3e38, 0, 0]}, "position": [3e38, 0, 0]})"),
               "lights[0].transform puts the light at a position beyond float range");
  // Fine: a spot of 180 degrees (every direction) with no falloff, a point light of zero intensity.
  EXPECT_NO_THROW(load_scene(lights(spot + R"("cone_angle_deg": 180, "falloff_start_deg": 180})")));
  EXPECT_NO_THROW(load_scene(lights(R"({"type": "point", "intensity": [0, 0, 0]})")));
}

TEST_F(SceneLoader, SecondEnvironmentLight) {
  fs::path f = scene(kHead + R"(  "lights": [{"type": "environment", "radiance": [1, 1, 1]},
             {"type": "environment", "radiance": [2, 2, 2]}]
})");
  EXPECT_ERROR(f, "s.json:5:14: lights[1] is a second environment light");
}

TEST_F(SceneLoader, AllDegenerateMeshIsError) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "mesh", "material": "grey", "vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0]],
               "indices": [0, 1, 2, 1, 1, 2]}]
})");
  EXPECT_ERROR(f, "s.json:6:27: objects[0].indices leaves no triangles (all 2 are degenerate)");
}

TEST_F(SceneLoader, MeshIndexOutOfRange) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "mesh", "material": "grey", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
               "indices": [0, 1, 3]}]
})");
  EXPECT_ERROR(f, "s.json:6:34: objects[0].indices[2] must be a vertex index in [0, 2], got 3");
}

TEST_F(SceneLoader, MissingSceneFile) {
  fs::path f = temp_dir() / "nope.json";
  EXPECT_ERROR(f, "nope.json: cannot open: No such file or directory");
}

TEST_F(SceneLoader, EveryTruncationOfTheExampleIsAnInputError) {
  // Exercises the syntax-error path (and, under ASan, the position scanner) on broken text.
  std::string text = read(kExamples / "all-features.json");
  ASSERT_GT(text.size(), 100u);
  fs::path file = scene("");
  for (size_t n = 0; n < text.size() - 2; n += 7) {
    write(file, text.substr(0, n));
    EXPECT_THROW(load_scene(file), InputError) << n;
  }
}

TEST_F(SceneLoader, TopLevelMustBeAnObject) {
  EXPECT_ERROR(scene("[1, 2]"), "s.json:1:1: the scene must be a JSON object, got [1,2]");
}

// --- bad input: OBJ / MTL -----------------------------------------------------------------

TEST_F(SceneLoader, MissingObjFile) {
  fs::path f = scene(kHead + R"(  "objects": [
    {"type": "obj",
     "file": "missing.obj"}
  ]
})");
  EXPECT_ERROR(f, "s.json:6:14: objects[0].file cannot open \"missing.obj\": No such file or directory");
}

TEST_F(SceneLoader, ObjFaceIndexOutOfRange) {
  fs::path f =
      scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"bad-index.obj\"}]\n}\n", {"bad-index.obj"});
  EXPECT_ERROR(f, "bad-index.obj:7: face index 9 out of range (4 vertices)");
}

TEST_F(SceneLoader, ObjMissingMtl) {
  fs::path f =
      scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"missing-mtl.obj\"}]\n}\n", {"missing-mtl.obj"});
  EXPECT_ERROR(f, "missing-mtl.obj:2: mtllib cannot open \"no-such.mtl\": No such file or directory");
}

TEST_F(SceneLoader, ObjUnreadableMtl) {
  // A directory where the MTL file should be: opening it for reading fails.
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"m.obj\"}]\n}\n");
  fs::create_directory(f.parent_path() / "lib.mtl");
  write(f.parent_path() / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib lib.mtl\nf 1 2 3\n");
  EXPECT_ERROR(f, "m.obj:4: mtllib cannot open \"lib.mtl\": Is a directory");
}

TEST_F(SceneLoader, ObjUnknownUsemtl) {
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"unknown-usemtl.obj\"}]\n}\n",
                     {"unknown-usemtl.obj", "two.mtl"});
  EXPECT_ERROR(f, "unknown-usemtl.obj:7: usemtl \"purple\" names no material");
}

TEST_F(SceneLoader, ObjMaterialOverrideSkipsMtlNames) {
  // With a JSON material the OBJ's own materials are not consulted at all.
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "obj", "file": "unknown-usemtl.obj", "material": "grey"}]
})",
                     {"unknown-usemtl.obj", "two.mtl"});
  SceneDesc s = load_scene(f);
  ASSERT_EQ(s.shapes.size(), 1u);
  EXPECT_EQ(s.shapes[0].mesh.indices.size(), 6u);
  EXPECT_EQ(s.materials.size(), 1u);
}

TEST_F(SceneLoader, ObjFacesWithoutMaterialGetDefaultDiffuse) {
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"bad.obj\"}]\n}\n");
  write(f.parent_path() / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  SceneDesc s = load_scene(f);
  ASSERT_EQ(s.shapes.size(), 1u);
  EXPECT_EQ(material_of(s, s.shapes[0]).name, "bad/default");
  EXPECT_EQ(material_of(s, s.shapes[0]).type, MaterialType::Diffuse);
}

TEST_F(SceneLoader, ObjRelativeIndicesAndNormals) {
  // A quad through negative (relative) indices with per-corner normals: triangulated, normals kept.
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"q.obj\"}]\n}\n");
  write(f.parent_path() / "q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf -4//-1 -3//-1 -2//-1 -1//-1\n");
  SceneDesc s = load_scene(f);
  ASSERT_EQ(s.shapes.size(), 1u);
  const MeshData& m = s.shapes[0].mesh;
  EXPECT_EQ(m.indices.size(), 6u);
  ASSERT_EQ(m.normals.size(), m.positions.size());
  expect_vec(m.normals[0], 0, 0, 1);
}

// One mesh vertex per distinct (position, normal, texture coordinate), numbered in order of
// first use: a cube with one normal per face gives each of its 8 positions 3 vertices, a
// corner the two triangles of a face share stays one, and a second use of a combination
// after a different one (position 1 again with the first normal) reuses the first vertex.
TEST_F(SceneLoader, ObjVerticesAreTheDistinctPositionNormalPairsInOrderOfFirstUse) {
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"c.obj\"}]\n}\n");
  std::string obj;
  for (int x : {0, 1})
    for (int y : {0, 1})
      for (int z : {0, 1}) {
        char line[32];
        std::snprintf(line, sizeof line, "v %d %d %d\n", x, y, z);
        obj += line;
      }
  // Positions are 1 + 4x + 2y + z; the faces x = 0, x = 1, y = 0, y = 1, z = 0, z = 1.
  obj += "vn -1 0 0\nvn 1 0 0\nvn 0 -1 0\nvn 0 1 0\nvn 0 0 -1\nvn 0 0 1\n";
  // Each face as two triangles (a b c, a c d), so that the order of first use is a, b, c, d.
  const int faces[6][4] = {{1, 2, 4, 3}, {5, 7, 8, 6}, {1, 5, 6, 2}, {3, 4, 8, 7}, {1, 3, 7, 5}, {2, 6, 8, 4}};
  const int halves[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (int k = 0; k < 6; ++k)
    for (const auto& t : halves) {
      char line[64];
      std::snprintf(line, sizeof line, "f %d//%d %d//%d %d//%d\n", faces[k][t[0]], k + 1, faces[k][t[1]], k + 1,
                    faces[k][t[2]], k + 1);
      obj += line;
    }
  obj += "f 1//1 2//1 4//1\n";  // position 1 with the x = 0 normal again, after others
  write(f.parent_path() / "c.obj", obj);
  SceneDesc s = load_scene(f);
  ASSERT_EQ(s.shapes.size(), 1u);
  const MeshData& m = s.shapes[0].mesh;
  ASSERT_EQ(m.positions.size(), 24u);
  ASSERT_EQ(m.normals.size(), 24u);
  ASSERT_EQ(m.indices.size(), 3u * 13u);
  // The first face's four corners are vertices 0..3 in order; its last triangle repeats them.
  expect_vec(m.positions[2], 0, 1, 1), expect_vec(m.normals[2], -1, 0, 0);
  EXPECT_EQ(std::vector<uint32_t>(m.indices.end() - 3, m.indices.end()), (std::vector<uint32_t>{0, 1, 2}));
  // Position 1 (the origin) is vertices 0 (x = 0), 8 (y = 0) and 16 (z = 0).
  for (uint32_t i : {0u, 8u, 16u}) expect_vec(m.positions[i], 0, 0, 0);
  expect_vec(m.normals[8], 0, -1, 0), expect_vec(m.normals[16], 0, 0, -1);
  for (std::size_t t = 0; t + 3 <= m.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const Vec3 n = m.normals[m.indices[t + k]], n0 = m.normals[m.indices[t]];
      EXPECT_TRUE(n.x == n0.x && n.y == n0.y && n.z == n0.z) << "triangle " << t / 3;
    }
}

TEST_F(SceneLoader, ObjRelativeIndexBeforeFirstVertex) {
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"q.obj\"}]\n}\n");
  write(f.parent_path() / "q.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n");
  EXPECT_ERROR(f, "q.obj:3: face index -3 out of range (2 vertices)");
}

TEST_F(SceneLoader, ObjMalformedFaceVertex) {
  // tinyobjloader would fail with a generic message; the check names the line and the token.
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"q.obj\"}]\n}\n");
  write(f.parent_path() / "q.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/ 3\n");
  EXPECT_ERROR(f, "q.obj:4: bad face vertex \"2/\"");
}

TEST_F(SceneLoader, ByteOrderMarkIgnored) {
  fs::path f = scene(
      "\xEF\xBB\xBF{\"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
      " \"film\": {\"width\": 8, \"height\": 0}}");
  EXPECT_ERROR(f, "s.json:2:33: film.height must be an integer in [1, 65536], got 0");
}

TEST_F(SceneLoader, AllDegenerateObjIsError) {
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"all-degenerate.obj\"}]\n}\n",
                     {"all-degenerate.obj"});
  EXPECT_ERROR(f, "s.json:4:39: objects[0].file \"all-degenerate.obj\" has no triangles (all 1 are degenerate)");
}

// --- JSON locations -----------------------------------------------------------------------

TEST(JsonLocations, PathsQuoteKeysThatAreNotIdentifiers) {
  EXPECT_EQ(json_key_path(json_key_path("", "materials"), "my mat"), "materials[\"my mat\"]");
  EXPECT_EQ(json_index_path(json_key_path("", "objects"), 2), "objects[2]");
}

TEST(JsonLocations, ColumnsCountCharactersNotBytes) {
  std::string text = "{\"materials\": {\"caf\xC3\xA9\": 1, \"b\": [true, 2]}}";
  JsonLocations at(text);
  auto v = at.value("materials.b[1]");
  ASSERT_TRUE(v);
  EXPECT_EQ(v->line, 1);
  EXPECT_EQ(v->col, 39);  // the e-acute is two bytes but one column
  EXPECT_EQ(at.source(*v), "2");
  auto k = at.key("materials[\"caf\xC3\xA9\"]");
  ASSERT_TRUE(k);
  EXPECT_EQ(k->col, 16);
}

// --- bad input: hostile nesting, bytes and OBJ files -------------------------------------

namespace {
std::string nested_arrays(size_t depth, bool closed) {
  std::string s(depth, '[');
  if (closed) s += "1" + std::string(depth, ']');
  return s;
}
}  // namespace

TEST_F(SceneLoader, DeeplyNestedValueIsRefusedAtTheLimitNotCrashing) {
  // 10^5 levels at camera.position used to overflow the stack while formatting "got <value>".
  fs::path f = scene("{\n  \"camera\": {\"position\": " + nested_arrays(100000, true) +
                     ", \"look_at\": [0, 0, 0]},\n  \"film\": {\"width\": 8, \"height\": 8}\n}\n");
  // Depth 1 is the top-level object, 2 camera, 3 the outer '[' at column 26; depth 65 is the
  // 63rd '[' (column 26 + 62).
  EXPECT_ERROR(f, "s.json:2:88: JSON nested deeper than 64 levels");
}

TEST_F(SceneLoader, MillionDeepDocumentIsRefusedWhetherClosedOrNot) {
  for (bool closed : {true, false}) {
    fs::path f = scene(nested_arrays(1000000, closed));
    EXPECT_ERROR(f, "s.json:1:65: JSON nested deeper than 64 levels");
  }
}

TEST_F(SceneLoader, NestingAtTheLimitIsParsedAndReportedShortly) {
  // 64 levels are accepted by the parser; the value is then wrong, and its rendering is short.
  fs::path f = scene("{\n  \"camera\": {\"position\": " + nested_arrays(62, true) +
                     ", \"look_at\": [0, 0, 0]},\n  \"film\": {\"width\": 8, \"height\": 8}\n}\n");
  std::string m = load_error(f);
  EXPECT_NE(m.find("camera.position must be an array of 3 numbers, got [[[[...]]]]"), std::string::npos) << m;
  EXPECT_LT(m.size(), 200u) << m;
}

TEST_F(SceneLoader, SyntaxErrorBeforeTheDepthLimitIsReportedFirst) {
  fs::path f = scene("{\"camera\": tru, \"x\": " + nested_arrays(1000, false));
  EXPECT_ERROR(f, "s.json:1:15: JSON syntax error");
}

TEST_F(SceneLoader, BracketsInsideStringsDoNotCountAsNesting) {
  fs::path f = scene(kHead + "  \"materials\": {\"" + std::string(200, '[') + "\": {\"type\": \"diffuse\"}}\n}\n");
  EXPECT_NO_THROW(load_scene(f));
}

TEST_F(SceneLoader, LongValuesAreAbbreviatedInMessages) {
  std::string big = "[";
  for (int i = 0; i < 100000; ++i) big += (i ? ",\"" : "\"") + std::to_string(i) + "\"";
  big += "]";
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"sphere\", \"radius\": 1, \"material\": " + big + "}]\n}\n");
  std::string m = load_error(f);
  EXPECT_NE(m.find("must be a string, got [\"0\",\"1\""), std::string::npos) << m;
  EXPECT_NE(m.find("..."), std::string::npos) << m;
  EXPECT_LT(m.size(), 200u) << m;
}

TEST_F(SceneLoader, InvalidUtf8IsEscapedInMessages) {
  fs::path f = scene("{\n  \"camera\": \xFF\xFE\x1B[31m\n}\n");
  std::string m = load_error(f);
  EXPECT_NE(m.find("s.json:2:13: JSON syntax error"), std::string::npos) << m;
  for (char c : m) EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7F) << m;
  EXPECT_NE(m.find("\\xFF"), std::string::npos) << m;
}

TEST_F(SceneLoader, EmptyObjIsNamedAndCalledEmpty) {
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"e.obj\"}]\n}\n");
  write(f.parent_path() / "e.obj", "");
  std::string m = load_error(f);
  EXPECT_NE(m.find("e.obj: empty file"), std::string::npos) << m;
}

TEST_F(SceneLoader, BinaryObjIsNamedAndCalledNotText) {
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"b.obj\"}]\n}\n");
  write(f.parent_path() / "b.obj", std::string("v 0 0 0\n\x7F"
                                               "ELF\x02\x01\x01\0\0\0",
                                               16));
  std::string m = load_error(f);
  EXPECT_NE(m.find("b.obj:2: not a text file (control byte 0x7F)"), std::string::npos) << m;
}

TEST_F(SceneLoader, ObjWithoutFacesSaysSo) {
  fs::path f = scene(kHead + "  \"objects\": [{\"type\": \"obj\", \"file\": \"v.obj\"}]\n}\n");
  write(f.parent_path() / "v.obj", "v 0 0 0\nv 1 0 0\n");
  EXPECT_ERROR(f, "objects[0].file \"v.obj\" has no triangles (no f lines)");
}

TEST_F(SceneLoader, SppAboveTheSharedLimitIsRefused) {
  fs::path f = scene(kHead + "  \"sampler\": {\"spp\": 16777217}\n}\n");
  EXPECT_ERROR(f, "s.json:4:22: sampler.spp must be an integer in [1, 16777216], got 16777217");
}

TEST_F(SceneLoader, NegativeSeedIsRefusedWithTheRange) {
  fs::path f = scene(kHead + "  \"sampler\": {\"seed\": -1}\n}\n");
  EXPECT_ERROR(f, "s.json:4:23: sampler.seed must be an integer in [0, 18446744073709551615], got -1");
}

// --- environment images -------------------------------------------------------------------

namespace {

// Writes a tiny float EXR through the image module (w x h RGB, top row first).
void write_exr(const fs::path& file, int w, int h, const std::vector<float>& rgb) {
  PdrtImageWrite im{};
  im.path = file.c_str(), im.format = "exr";
  im.width = w, im.height = h, im.channels = 3, im.z_channel = -1;
  im.pixels = rgb.data();
  char error[512] = "";
  ASSERT_EQ(image_module().write(&im, error, sizeof error), 0) << error;
}

std::vector<float> ramp(int n) {
  std::vector<float> v;
  for (int i = 0; i < 3 * n; ++i) v.push_back(0.25f * float(i));
  return v;
}

// A scene with one light on line 4 (column 14 is its opening brace).
fs::path light_scene(const std::string& light) { return scene(kHead + "  \"lights\": [" + light + "]\n}\n"); }

struct ScopedAssets {
  explicit ScopedAssets(const fs::path& dir) { ::setenv("PDRT_ASSETS", dir.c_str(), 1); }
  ~ScopedAssets() { ::unsetenv("PDRT_ASSETS"); }
};

}  // namespace

TEST_F(SceneLoader, EnvironmentImageIsReadWithScaleAndRotation) {
  fs::path f = light_scene(R"({"type": "environment", "file": "e.exr", "scale": [1, 2, 0.5], "rotation_deg": -45})");
  write_exr(f.parent_path() / "e.exr", 4, 2, ramp(8));
  SceneDesc s = load_scene(f);
  ASSERT_TRUE(s.environment.has_map());
  EXPECT_EQ(s.environment.width, 4);
  EXPECT_EQ(s.environment.height, 2);
  EXPECT_EQ(s.environment.rgb, ramp(8));
  expect_vec(s.environment.scale, 1, 2, 0.5f);
  EXPECT_FLOAT_EQ(s.environment.rotation_deg, -45);
  EXPECT_EQ(s.environment.file, (f.parent_path() / "e.exr").string());
  expect_vec(s.environment.radiance, 0, 0, 0);
}

TEST_F(SceneLoader, EnvironmentScaleDefaultsToOneAndTakesANumber) {
  fs::path f = light_scene(R"({"type": "environment", "file": "e.exr"})");
  write_exr(f.parent_path() / "e.exr", 2, 1, ramp(2));
  expect_vec(load_scene(f).environment.scale, 1, 1, 1);
  EXPECT_FLOAT_EQ(load_scene(f).environment.rotation_deg, 0);
  write(f, kHead + R"(  "lights": [{"type": "environment", "file": "e.exr", "scale": 3}]})");
  expect_vec(load_scene(f).environment.scale, 3, 3, 3);
}

TEST_F(SceneLoader, EnvironmentRadianceAndFileTogetherIsRefused) {
  fs::path f = light_scene(R"({"type": "environment", "radiance": [1, 1, 1], "file": "e.exr"})");
  EXPECT_ERROR(f, "s.json:4:61: lights[0].file cannot be combined with radiance");
}

TEST_F(SceneLoader, EnvironmentWithoutRadianceOrFileIsRefused) {
  EXPECT_ERROR(light_scene(R"({"type": "environment"})"), "s.json:4:14: lights[0] needs radiance");
}

TEST_F(SceneLoader, EnvironmentMissingImageNamesTheFileAndKey) {
  fs::path f = light_scene(R"({"type": "environment", "file": "nope.exr"})");
  EXPECT_ERROR(f, "s.json:4:46: lights[0].file cannot open \"nope.exr\": no such file in the scene's directory");
  EXPECT_ERROR(light_scene(R"({"type": "environment", "file": ""})"), "lights[0].file must name an image file");
}

TEST_F(SceneLoader, EnvironmentUnreadableImageNamesTheFileAndKey) {
  fs::path f = light_scene(R"({"type": "environment", "file": "bad.exr"})");
  write(f.parent_path() / "bad.exr", "not an image at all");
  EXPECT_ERROR(f, "s.json:4:46: lights[0].file cannot read \"bad.exr\": ");
}

TEST_F(SceneLoader, EnvironmentNonFiniteOrNegativeTexelIsRefused) {
  fs::path f = light_scene(R"({"type": "environment", "file": "e.exr"})");
  std::vector<float> rgb = ramp(6);
  rgb[3 * 4 + 2] = std::nanf("");
  write_exr(f.parent_path() / "e.exr", 3, 2, rgb);
  EXPECT_ERROR(f, "lights[0].file \"e.exr\" has a non-finite value nan at texel (1, 1) channel 2");
  rgb[3 * 4 + 2] = INFINITY;
  write_exr(f.parent_path() / "e.exr", 3, 2, rgb);
  EXPECT_ERROR(f, "lights[0].file \"e.exr\" has a non-finite value inf at texel (1, 1) channel 2");
  rgb[3 * 4 + 2] = 1;
  rgb[1] = -0.5f;
  write_exr(f.parent_path() / "e.exr", 3, 2, rgb);
  EXPECT_ERROR(f, "lights[0].file \"e.exr\" has a negative value -0.5 at texel (0, 0) channel 1");
}

TEST_F(SceneLoader, EnvironmentBadScaleOrRotationIsRefused) {
  fs::path f = light_scene(R"({"type": "environment", "file": "e.exr", "scale": -1})");
  write_exr(f.parent_path() / "e.exr", 2, 1, ramp(2));
  EXPECT_ERROR(f, "s.json:4:64: lights[0].scale must be >= 0, got -1");
  write(f, kHead + R"(  "lights": [{"type": "environment", "file": "e.exr", "scale": [1, -2, 1]}]})");
  EXPECT_ERROR(f, "lights[0].scale must have components >= 0");
  write(f, kHead + R"(  "lights": [{"type": "environment", "file": "e.exr", "rotation_deg": "north"}]})");
  EXPECT_ERROR(f, "lights[0].rotation_deg must be a number");
  write(f, kHead + R"(  "lights": [{"type": "environment", "file": "e.exr", "rotation": 90}]})");
  EXPECT_ERROR(f, "rotation");
  write(f, kHead + R"(  "lights": [{"type": "environment", "radiance": [1, 1, 1], "rotation_deg": 90}]})");
  EXPECT_ERROR(f, "lights[0].rotation_deg applies to an image (file) only");
  write(f, kHead + R"(  "lights": [{"type": "environment", "radiance": [1, 1, 1], "scale": 2}]})");
  EXPECT_ERROR(f, "lights[0].scale applies to an image (file) only");
}

// Search order: the scene's directory first, then $PDRT_ASSETS (else the build's assets).
TEST_F(SceneLoader, EnvironmentImageIsFoundInTheGeneratedAssets) {
  fs::path f = light_scene(R"({"type": "environment", "file": "sky_test.exr"})");
  const fs::path assets = f.parent_path() / "assets";
  fs::create_directories(assets);
  write_exr(assets / "sky_test.exr", 2, 1, ramp(2));
  {
    ScopedAssets env(assets);
    SceneDesc s = load_scene(f);
    EXPECT_EQ(s.environment.width, 2);
    EXPECT_EQ(s.environment.file, (assets / "sky_test.exr").string());
    write_exr(f.parent_path() / "sky_test.exr", 3, 1, ramp(3));  // the scene's own copy wins
    EXPECT_EQ(load_scene(f).environment.width, 3);
  }
  fs::remove(f.parent_path() / "sky_test.exr");
  EXPECT_ERROR(f, "cannot open \"sky_test.exr\": no such file in the scene's directory or the generated assets");
}

// The build generates the sky every example may use.
TEST_F(SceneLoader, GeneratedSkyIsFoundFromAnyScene) {
  SceneDesc s = load_scene(light_scene(R"({"type": "environment", "file": "sky.exr"})"));
  EXPECT_EQ(s.environment.width, 512);
  EXPECT_EQ(s.environment.height, 256);
}

// --- camera projection, screen window and film crop window ----------------------------------

namespace {

// A scene whose camera (line 2) or film (line 3) object ends with `extra`.
std::string projection_scene(const std::string& camera_extra, const std::string& film_extra) {
  return "{\n  \"camera\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0]" +
         (camera_extra.empty() ? "" : ", " + camera_extra) + "},\n  \"film\": {\"width\": 8, \"height\": 8" +
         (film_extra.empty() ? "" : ", " + film_extra) + "}\n}";
}

}  // namespace

TEST_F(SceneLoader, ExampleProjectionScreenAndCropWindow) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  EXPECT_EQ(s.camera.projection, CameraDesc::Projection::Orthographic);
  EXPECT_FLOAT_EQ(s.camera.ortho_height, 3.5f);
  EXPECT_TRUE(s.camera.has_screen_window);
  EXPECT_FLOAT_EQ(s.camera.screen_window[0], -2.6f);
  EXPECT_FLOAT_EQ(s.camera.screen_window[3], 1.9f);
  EXPECT_FLOAT_EQ(s.film.crop_window[0], 0.05f);
  EXPECT_FLOAT_EQ(s.film.crop_window[3], 0.95f);
}

TEST_F(SceneLoader, ProjectionDefaultsArePerspectiveWithoutWindows) {
  SceneDesc s = load_scene(scene(projection_scene("", "")));
  EXPECT_EQ(s.camera.projection, CameraDesc::Projection::Perspective);
  EXPECT_FALSE(s.camera.has_screen_window);
  EXPECT_FLOAT_EQ(s.camera.ortho_height, 2);
  EXPECT_EQ(s.film.crop_window, (std::array<float, 4>{0, 1, 0, 1}));
  s = load_scene(scene(projection_scene("\"type\": \"orthographic\", \"screen_window\": [-1, 3, 0, 2]",
                                        "\"crop_window\": [0, 0.25, 0.5, 1]")));
  EXPECT_EQ(s.camera.projection, CameraDesc::Projection::Orthographic);
  EXPECT_EQ(s.camera.screen_window, (std::array<float, 4>{-1, 3, 0, 2}));
  EXPECT_EQ(s.film.crop_window, (std::array<float, 4>{0, 0.25f, 0.5f, 1}));
}

// Every bad value of camera.type, ortho_height, screen_window and film.crop_window, with its position.
TEST_F(SceneLoader, BadProjectionScreenOrCropWindow) {
  const fs::path f = scene("");
  const std::pair<std::string, std::string> camera_cases[] = {
      {"\"type\": \"fisheye\"", "s.json:2:67: camera.type must be one of perspective, orthographic, got \"fisheye\""},
      {"\"ortho_height\": 2", "s.json:2:59: camera.ortho_height needs \"type\": \"orthographic\""},
      {"\"type\": \"orthographic\", \"ortho_height\": 0", "s.json:2:99: camera.ortho_height must be > 0, got 0"},
      {"\"screen_window\": [-1, 1, -1]", "s.json:2:76: camera.screen_window must be [x0, x1, y0, y1], got [-1,1,-1]"},
      {"\"screen_window\": \"wide\"", "s.json:2:76: camera.screen_window must be [x0, x1, y0, y1], got \"wide\""},
      {"\"screen_window\": [1, -1, -1, 1]", "s.json:2:76: camera.screen_window must have x0 < x1, got [1,-1,-1,1]"},
      {"\"screen_window\": [-1, 1, 0.5, 0.5]",
       "s.json:2:76: camera.screen_window must have y0 < y1, got [-1,1,0.5,0.5]"},
      {"\"screen_window\": [-1, 1e999, -1, 1]",
       "s.json:2:81: camera.screen_window[1] must be a finite number, got 1e999"},
      {"\"screen_window\": [-1, \"a\", -1, 1]", "s.json:2:81: camera.screen_window[1] must be a number"},
      {"\"screen_window\": [-1, 1, -1, 2e6]",
       "s.json:2:76: camera.screen_window must have every bound within [-1e6, 1e6], got [-1,1,-1,2000000.0]"},
  };
  for (const auto& [extra, message] : camera_cases) {
    write(f, projection_scene(extra, ""));
    EXPECT_ERROR(f, message);
  }
  const std::pair<std::string, std::string> film_cases[] = {
      {"\"crop_window\": [0, 1, 0]", "s.json:3:52: film.crop_window must be [x0, x1, y0, y1], got [0,1,0]"},
      {"\"crop_window\": [0.5, 0.2, 0, 1]", "s.json:3:52: film.crop_window must have x0 < x1, got [0.5,0.2,0,1]"},
      {"\"crop_window\": [0, 1, 0.7, 0.7]", "s.json:3:52: film.crop_window must have y0 < y1, got [0,1,0.7,0.7]"},
      {"\"crop_window\": [-0.1, 1, 0, 1]",
       "s.json:3:52: film.crop_window must lie within [0, 1] (fractions of the film, y down), got [-0.1,1,0,1]"},
      {"\"crop_window\": [0, 1.5, 0, 1]", "s.json:3:52: film.crop_window must lie within [0, 1]"},
      {"\"crop_window\": [0.51, 0.6, 0, 1]",
       "s.json:3:52: film.crop_window covers no pixel of the 8x8 film (pixels ceil(size * bound) are [5, 5) x [0, 8)), "
       "got [0.51,0.6,0,1]"},
      {"\"crop_window\": [0, 1, 0, 1e999]", "s.json:3:62: film.crop_window[3] must be a finite number, got 1e999"},
  };
  for (const auto& [extra, message] : film_cases) {
    write(f, projection_scene("", extra));
    EXPECT_ERROR(f, message);
  }
}

// --- prototypes and instances -------------------------------------------------------------

namespace {

// kHead, a grey and a lamp material (line 4), a prototype "tree" of a sphere and a quad
// (lines 5-6), then `rest` (line 7 on).
std::string with_prototype(const std::string& rest) {
  return kHead + R"(  "materials": {"grey": {"type": "diffuse"}, "lamp": {"type": "emitter", "radiance": [1, 1, 1]}},
  "prototypes": {"tree": [{"type": "sphere", "material": "grey", "radius": 1, "transform": {"translate": [0, 2, 0]}},
                          {"type": "quad", "material": "grey", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 0, 1]}]},
)" + rest;
}

}  // namespace

TEST_F(SceneLoader, PrototypesAndInstancesLoad) {
  fs::path f = scene(
      with_prototype(R"(  "objects": [{"type": "instance", "prototype": "tree", "transform": {"translate": [5, 0, 0]}},
              {"type": "sphere", "material": "grey", "radius": 0.5},
              {"type": "instance", "prototype": "tree",
               "motion": [{"time": 0}, {"time": 1, "translate": [0, 0, 1], "scale": [1, 2, 1]}]}]
})"));
  SceneDesc s = load_scene(f);
  ASSERT_EQ(s.prototypes.size(), 1u);
  EXPECT_EQ(s.prototypes[0].name, "tree");
  ASSERT_EQ(s.prototypes[0].shapes.size(), 2u);
  EXPECT_EQ(s.prototypes[0].shapes[0].kind, ShapeDesc::Kind::Sphere);
  expect_vec(s.prototypes[0].shapes[0].transform.point({0, 0, 0}), 0, 2, 0);
  EXPECT_EQ(s.prototypes[0].shapes[1].mesh.indices.size(), 6u);
  ASSERT_EQ(s.shapes.size(), 1u);  // the plain sphere
  ASSERT_EQ(s.instances.size(), 2u);
  EXPECT_EQ(s.instances[0].prototype, 0);
  expect_vec(s.instances[0].transform.point({0, 0, 0}), 5, 0, 0);
  EXPECT_TRUE(s.instances[0].motion.empty());
  ASSERT_EQ(s.instances[1].motion.size(), 2u);  // an instance's keys may scale non-uniformly
  EXPECT_FLOAT_EQ(s.instances[1].motion[1].scale.y, 2);
  EXPECT_NE(s.instances[1].where.find("objects[2]"), std::string::npos);
}

TEST_F(SceneLoader, UnusedPrototypeIsFine) {
  SceneDesc s = load_scene(scene(with_prototype("  \"objects\": []\n}")));
  EXPECT_EQ(s.prototypes.size(), 1u);
  EXPECT_TRUE(s.instances.empty());
}

TEST_F(SceneLoader, PrototypeObjectsMayComeFromAnObjFile) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "prototypes": {"box": [{"type": "obj", "file": "tri.obj", "material": "grey"}]},
  "objects": [{"type": "instance", "prototype": "box"}, {"type": "instance", "prototype": "box"}]
})");
  write(f.parent_path() / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  SceneDesc s = load_scene(f);
  ASSERT_EQ(s.prototypes.size(), 1u);
  ASSERT_EQ(s.prototypes[0].shapes.size(), 1u);
  EXPECT_EQ(s.prototypes[0].shapes[0].mesh.indices.size(), 3u);
  EXPECT_TRUE(s.shapes.empty());
  EXPECT_EQ(s.instances.size(), 2u);
}

TEST_F(SceneLoader, UnknownPrototypeIsRefusedNamingTheKnownOnes) {
  EXPECT_ERROR(scene(with_prototype("  \"objects\": [{\"type\": \"instance\", \"prototype\": \"bush\"}]\n}")),
               "s.json:7:49: objects[0].prototype is not a prototype (prototypes: \"tree\"), got \"bush\"");
  EXPECT_ERROR(scene(kHead + "  \"objects\": [{\"type\": \"instance\", \"prototype\": \"bush\"}]\n}"),
               "s.json:4:49: objects[0].prototype is not a prototype (the scene has no \"prototypes\"), got \"bush\"");
}

TEST_F(SceneLoader, InstanceNeedsAPrototypeAndKnowsItsKeys) {
  EXPECT_ERROR(scene(with_prototype("  \"objects\": [{\"type\": \"instance\"}]\n}")),
               "s.json:7:15: objects[0] missing required key \"prototype\"");
  EXPECT_ERROR(scene(with_prototype(
                   "  \"objects\": [{\"type\": \"instance\", \"prototype\": \"tree\", \"material\": \"grey\"}]\n}")),
               "objects[0].material");
  EXPECT_ERROR(scene(with_prototype("  \"objects\": [{\"type\": \"instance\", \"prototype\": 3}]\n}")),
               "s.json:7:49: objects[0].prototype must be a string, got 3");
}

TEST_F(SceneLoader, EmptyPrototypeIsRefused) {
  EXPECT_ERROR(scene(kHead + "  \"prototypes\": {\"tree\": []},\n  \"objects\": []\n}"),
               "s.json:4:26: prototypes.tree must hold at least one object");
  EXPECT_ERROR(scene(kHead + "  \"prototypes\": {\"tree\": {}},\n  \"objects\": []\n}"),
               "s.json:4:26: prototypes.tree must be an array of objects, got {}");
  EXPECT_ERROR(scene(kHead + "  \"prototypes\": [],\n  \"objects\": []\n}"),
               "s.json:4:17: prototypes must be an object");
  EXPECT_ERROR(
      scene(kHead + "  \"prototypes\": {\"\": [{\"type\": \"sphere\", \"radius\": 1}]},\n  \"objects\": []\n}"),
      "s.json:4:18: prototypes[\"\"] prototype name must not be empty");
}

TEST_F(SceneLoader, InstanceInsideAPrototypeIsRefused) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "prototypes": {"forest": [{"type": "instance", "prototype": "tree"}],
                 "tree": [{"type": "sphere", "material": "grey", "radius": 1}]},
  "objects": []
})");
  EXPECT_ERROR(f,
               "s.json:5:38: prototypes.forest[0].type is not allowed inside a prototype (instances do not nest), got "
               "\"instance\"");
}

TEST_F(SceneLoader, MotionInsideAPrototypeIsRefused) {
  fs::path f = scene(kHead + R"(  "materials": {"grey": {"type": "diffuse"}},
  "prototypes": {"tree": [{"type": "sphere", "material": "grey", "radius": 1, "motion": [{"time": 0}]}]},
  "objects": []
})");
  EXPECT_ERROR(f,
               "s.json:5:79: prototypes.tree[0].motion is not allowed inside a prototype (give the instance a motion)");
}

TEST_F(SceneLoader, EmitterInsideAPrototypeIsRefused) {
  fs::path f = scene(kHead + R"(  "materials": {"lamp": {"type": "emitter", "radiance": [1, 1, 1]}},
  "prototypes": {"tree": [{"type": "sphere", "material": "lamp", "radius": 1}]},
  "objects": []
})");
  EXPECT_ERROR(f,
               "s.json:5:58: prototypes.tree[0].material is an emitter; emitters cannot be inside a prototype "
               "(instanced area lights are not supported), got \"lamp\"");
  fs::path obj = scene(kHead + R"(  "prototypes": {"tree": [{"type": "obj", "file": "lamp.obj"}]},
  "objects": []
})");
  write(obj.parent_path() / "lamp.obj", "mtllib lamp.mtl\nusemtl glow\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write(obj.parent_path() / "lamp.mtl", "newmtl glow\nKe 1 1 1\n");
  EXPECT_ERROR(obj,
               "s.json:4:51: prototypes.tree[0].file \"lamp.obj\" has an emitting material (Ke) \"lamp/glow\"; "
               "emitters cannot be inside a prototype");
}

TEST_F(SceneLoader, ExamplePrototypesAndInstances) {
  SceneDesc s = load_scene(kExamples / "all-features.json");
  ASSERT_EQ(s.prototypes.size(), 1u);
  EXPECT_EQ(s.prototypes[0].name, "post");
  EXPECT_EQ(s.prototypes[0].shapes.size(), 2u);
  ASSERT_EQ(s.instances.size(), 2u);
  expect_vec(s.instances[0].transform.point({0, 0, 1}), -0.6f, 0, 1.5f);
  EXPECT_TRUE(s.instances[0].motion.empty());
  ASSERT_EQ(s.instances[1].motion.size(), 2u);
  EXPECT_FLOAT_EQ(s.instances[1].motion[1].scale.y, 1.2f);
}
