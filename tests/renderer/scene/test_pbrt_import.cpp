// pbrt-v4 scenes as pdrt scenes (issue 18): each directive's effect on the scene description,
// what pdrt cannot represent reported (or refused with --strict), contradictory input refused
// with file:line:col, and a .pbrt scene rendering the image of its JSON equivalent.
#include "renderer/scene/pbrt/pbrt_matrix.h"
#include "renderer/scene/pbrt/pbrt_scene_builder.h"
#include "renderer/scene/pbrt/ply_mesh.h"
#include "renderer/scene/pbrt/pbrt_spectrum.h"
#include "renderer/scene/crop_window.h"
#include "sampling/core/errors.h"
#include "sampling/core/rng.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace pdrt;
using namespace pdrt::test;

namespace {

PbrtImport import(const std::string& text, bool strict = false) {
  return build_pbrt_scene(parse_pbrt_text(text, "s.pbrt", "."), strict);
}

std::string import_error(const std::string& text, bool strict = false) {
  try {
    import(text, strict);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError for: " << text;
  return "";
}

// The message load_pbrt_scene refuses `file` with (a failure, and "", when it accepts it).
std::string file_import_error(const std::filesystem::path& file) {
  try {
    load_pbrt_scene(file, false);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError for " << file;
  return "";
}

// The message load_ply refuses `file` with, shown as `shown` (a failure, and "", when it accepts it).
std::string ply_error(const std::filesystem::path& file, const std::string& shown) {
  try {
    load_ply(file, shown);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError for " << file;
  return "";
}

// The InputError that building tests/data/fuzz/pbrt/`name` (an input a fuzzer found) gives.
std::string fuzz_pbrt_error(const std::string& name) {
  const std::filesystem::path file = std::filesystem::path(PDRT_TEST_DATA_DIR) / "fuzz" / "pbrt" / name;
  try {
    build_pbrt_scene(parse_pbrt_file(file), false);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted " << file;
  return "";
}

const char* kCamera = "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n";

// The report without its one line on colours pdrt multiplies per RGB channel, which must be there.
std::vector<std::string> report_besides_rgb(const std::vector<std::string>& report) {
  std::vector<std::string> rest;
  for (const std::string& line : report)
    if (line.find("per RGB channel where pbrt-v4 works per wavelength") == std::string::npos) rest.push_back(line);
  EXPECT_EQ(rest.size() + 1, report.size()) << "one line on RGB colours";
  return rest;
}

void expect_near(const Vec3& a, const Vec3& b, float tol, const std::string& what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << what << " component " << i;
}

// The render comparisons' pbrt header (camera, 48 x 32 film, 8 spp, depth 4, box filter) and
// lamp, and their hand-built twins.
const std::string kTwinHeader =
    "LookAt 0 1 -6  0 0.5 0  0 1 0\n"
    "Camera \"perspective\" \"float fov\" 35\n"
    "Film \"rgb\" \"integer xresolution\" 48 \"integer yresolution\" 32\n"
    "Sampler \"independent\" \"integer pixelsamples\" 8\n"
    "Integrator \"path\" \"integer maxdepth\" 4\n"
    "PixelFilter \"box\"\n"
    "WorldBegin\n";
const std::string kTwinLamp =
    "AttributeBegin\n"
    "  AreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
    "  Shape \"trianglemesh\" \"point3 P\" [-1 3 -1  1 3 -1  1 3 1  -1 3 1] \"integer indices\" [0 1 2 0 2 3]\n"
    "AttributeEnd\n";

SceneDesc twin_scene() {
  SceneDesc j = base_scene(48, 32, 8);
  j.camera.position = {0, 1, -6};
  j.camera.look_at = {0, 0.5, 0};
  j.camera.vfov_deg = 35;
  j.camera.flip_x = true;  // pbrt's camera space is left-handed
  j.sampler.type = "random";
  j.sampler.seed = 0;
  j.integrator.max_depth = 4;
  return j;
}

void add_twin_lamp(SceneDesc& j) {
  ShapeDesc lq;
  lq.mesh.positions = {{-1, 3, -1}, {1, 3, -1}, {1, 3, 1}, {-1, 3, 1}};
  lq.mesh.indices = {0, 1, 2, 0, 2, 3};
  lq.material = add_material(j, emitter(4));
  j.shapes.push_back(lq);
}

// The imported scene `p` renders the hand-built `j` (48 x 32): every pixel within 1e-4 of the
// mean (float rounding in transforms), and the image not black. `j` takes p's camera up (pbrt's
// is the LookAt frame's, orthogonalised to the last bit differently) and both a pinhole at the
// same look-at distance (pbrt's 1e6 focal distance is one either way).
void expect_renders_agree(SceneDesc p, SceneDesc j) {
  j.camera.up = p.camera.up;
  p.camera.focus_distance = 0;
  j.camera.focus_distance = 0;
  p.camera.look_at = p.camera.position +
                     normalize(p.camera.look_at - p.camera.position) * length(j.camera.look_at - j.camera.position);
  const Image a = render_quietly(p).image, b = render_quietly(j).image;
  double worst = 0, sum = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) {
      worst = std::max(worst, std::abs(mean_rgb(a, x, y) - mean_rgb(b, x, y)));
      sum += mean_rgb(b, x, y);
    }
  EXPECT_GT(sum, 0);
  EXPECT_LT(worst, 1e-4 * std::max(1.0, sum / (48 * 32)));
}

}  // namespace

TEST(PbrtImport, LookAtCameraIsMirroredLikePbrtsLeftHandedCamera) {
  PbrtImport im = import(std::string(kCamera) +
                         "Film \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100\n"
                         "WorldBegin\nShape \"sphere\"\n");
  const CameraDesc& c = im.scene.camera;
  expect_near(c.position, {0, 0, -5}, 1e-6f, "position");
  expect_near(normalize(c.look_at - c.position), {0, 0, 1}, 1e-6f, "view direction");
  expect_near(c.up, {0, 1, 0}, 1e-6f, "up");
  // pbrt's camera +x is up x dir = (1, 0, 0) here; pdrt's film x is dir x up = (-1, 0, 0): flipped.
  EXPECT_TRUE(c.flip_x);
  EXPECT_FLOAT_EQ(c.vfov_deg, 30);  // landscape: fov spans the shorter, vertical side
  EXPECT_EQ(im.scene.film.width, 200);
  EXPECT_EQ(im.scene.film.height, 100);
  // Portrait: fov spans the horizontal side; tan(v/2) = tan(30/2) * 200 / 100.
  PbrtImport p = import(std::string(kCamera) +
                        "Film \"rgb\" \"integer xresolution\" 100 \"integer yresolution\" 200\n"
                        "WorldBegin\nShape \"sphere\"\n");
  EXPECT_NEAR(std::tan(p.scene.camera.vfov_deg * M_PI / 360), std::tan(15 * M_PI / 180) * 2, 1e-6);
  // A mirroring Scale before LookAt (common in exported scenes) makes the camera right-handed.
  PbrtImport s = import("Scale -1 1 1\n" + std::string(kCamera) + "WorldBegin\nShape \"sphere\"\n");
  EXPECT_FALSE(s.scene.camera.flip_x);
}

TEST(PbrtImport, TransformDirectivesComposeLikePbrt) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "Translate 1 2 3\n"
                         "CoordinateSystem \"here\"\n"
                         "AttributeBegin\n"
                         "  Rotate 90 0 0 1\n"  // (1, 0, 0) -> (0, 1, 0)
                         "  Scale 2 2 2\n"
                         "  Shape \"sphere\" \"float radius\" 0.5\n"
                         "  Shape \"trianglemesh\" \"point3 P\" [1 0 0  0 1 0  0 0 1]\n"
                         "AttributeEnd\n"
                         "TransformBegin\n"
                         "  Identity\n"
                         "  ConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0  10 20 30 1]\n"
                         "  Shape \"sphere\"\n"
                         "TransformEnd\n"
                         "Translate 100 0 0\n"
                         "CoordSysTransform \"here\"\n"
                         "Shape \"sphere\"\n");
  ASSERT_EQ(im.scene.shapes.size(), 4u);
  const Affine& a = im.scene.shapes[0].transform;
  expect_near(a.point({0, 0, 0}), {1, 2, 3}, 1e-6f, "sphere centre");
  expect_near(a.point({1, 0, 0}), {1, 4, 3}, 1e-5f, "rotated and scaled x");
  expect_near(im.scene.shapes[1].transform.point({0, 0, 1}), {1, 2, 5}, 1e-5f, "mesh vertex");
  expect_near(im.scene.shapes[2].transform.point({0, 0, 0}), {10, 20, 30}, 1e-6f, "Identity then ConcatTransform");
  expect_near(im.scene.shapes[3].transform.point({0, 0, 0}), {1, 2, 3}, 1e-6f, "CoordSysTransform");
}

TEST(PbrtImport, ActiveTransformGivesAShapeMotionKeysAtTheTransformTimes) {
  PbrtImport im = import(std::string(kCamera) +
                         "TransformTimes 0.25 0.75\n"
                         "WorldBegin\n"
                         "ActiveTransform EndTime\n"
                         "Translate 2 0 0\n"
                         "Rotate 90 0 1 0\n"
                         "ActiveTransform All\n"
                         "Shape \"sphere\"\n");
  ASSERT_EQ(im.scene.shapes.size(), 1u);
  const auto& m = im.scene.shapes[0].motion;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_FLOAT_EQ(m[0].time, 0.25f);
  EXPECT_FLOAT_EQ(m[1].time, 0.75f);
  expect_near(m[0].matrix().point({1, 0, 0}), {1, 0, 0}, 1e-6f, "start");
  expect_near(m[1].matrix().point({1, 0, 0}), {2, 0, -1}, 1e-5f, "end: rotated about y, then translated");
}

TEST(PbrtImport, DecomposeReassemblesTheMatrix) {
  // Scale (with a reflection), rotation and translation: T R S rebuilt within 1e-5.
  Rng rng(5);
  for (int i = 0; i < 50; ++i) {
    Mat4 m =
        Mat4::translate(rng.uniform() * 10 - 5, rng.uniform() * 10 - 5, rng.uniform() * 10 - 5) *
        Mat4::rotate(rng.uniform() * 360, rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) *
        Mat4::scale(i % 2 ? -(0.1 + rng.uniform()) : 0.1 + rng.uniform(), 0.1 + rng.uniform(), 0.1 + rng.uniform());
    double shear = 1;
    MotionKey k = decompose(m, &shear);
    EXPECT_LT(shear, 1e-9);
    for (Vec3 p : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.3f, -2, 1)})
      expect_near(k.matrix().point(p), m.point(p), 1e-4f, "case " + std::to_string(i));
  }
}

TEST(PbrtImport, MaterialsMapOntoPdrts) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "Material \"diffuse\" \"rgb reflectance\" [0.1 0.2 0.3]\n"
                         "Shape \"sphere\"\n"
                         "Material \"conductor\" \"spectrum eta\" \"metal-Ag-eta\" \"spectrum k\" \"metal-Ag-k\" "
                         "\"float roughness\" 0.01\n"
                         "Shape \"sphere\"\n"
                         "Material \"conductor\" \"rgb reflectance\" [0.9 0.5 0.1] \"bool remaproughness\" false "
                         "\"float roughness\" 0.25\n"
                         "Shape \"sphere\"\n"
                         "MakeNamedMaterial \"glass\" \"string type\" \"dielectric\" \"float eta\" 1.33\n"
                         "NamedMaterial \"glass\"\n"
                         "Shape \"sphere\"\n"
                         "Material \"interface\"\n"
                         "Shape \"sphere\"\n");
  ASSERT_EQ(im.scene.shapes.size(), 4u);  // the interface sphere bounds media only
  auto mat = [&](int i) { return im.scene.materials[im.scene.shapes[i].material]; };
  EXPECT_EQ(mat(0).type, MaterialType::Diffuse);
  expect_near(mat(0).albedo, {0.1f, 0.2f, 0.3f}, 0, "reflectance");
  EXPECT_EQ(mat(1).type, MaterialType::Conductor);
  expect_near(mat(1).eta, find_named_metal("Ag")->eta, 0, "Ag eta");
  // remapped: alpha = sqrt(0.01) = 0.1, pdrt roughness = sqrt(alpha).
  EXPECT_NEAR(mat(1).roughness, std::sqrt(0.1), 1e-6);
  // reflectance r: eta 1, k = 2 sqrt(r / (1 - r)) so that R0 = k^2 / (4 + k^2) = r.
  for (int c = 0; c < 3; ++c) {
    const float k = mat(2).k[c], r = (0.9f - 0.4f * c);
    EXPECT_NEAR(k * k / (4 + k * k), r, 1e-5) << c;
  }
  EXPECT_NEAR(mat(2).roughness, 0.5, 1e-6);  // alpha 0.25 given directly
  EXPECT_EQ(mat(3).type, MaterialType::Dielectric);
  EXPECT_FLOAT_EQ(mat(3).ior, 1.33f);
}

TEST(PbrtImport, LightsMapOntoPdrts) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "LightSource \"point\" \"point3 from\" [1 2 3] \"rgb I\" [1 2 3] \"float scale\" 2\n"
                         "LightSource \"spot\" \"point3 from\" [0 5 0] \"point3 to\" [0 0 0] \"float coneangle\" 40 "
                         "\"float conedeltaangle\" 10\n"
                         "LightSource \"distant\" \"point3 from\" [0 0 0] \"point3 to\" [0 -1 0] \"rgb L\" [3 3 3]\n"
                         "LightSource \"infinite\" \"rgb L\" [0.5 0.5 0.5]\n"
                         "AttributeBegin\n"
                         "AreaLightSource \"diffuse\" \"blackbody L\" 6500 \"float scale\" 4 \"bool twosided\" true\n"
                         "Shape \"sphere\"\n"
                         "AttributeEnd\n");
  const auto& dl = im.scene.delta_lights;
  ASSERT_EQ(dl.size(), 3u);
  EXPECT_EQ(dl[0].kind, DeltaLightDesc::Kind::Point);
  expect_near(dl[0].transform.point(dl[0].position), {1, 2, 3}, 1e-6f, "point position");
  expect_near(dl[0].intensity, {2, 4, 6}, 0, "I times scale");
  EXPECT_EQ(dl[1].kind, DeltaLightDesc::Kind::Spot);
  expect_near(dl[1].direction, {0, -1, 0}, 1e-6f, "spot axis");
  EXPECT_NEAR(dl[1].cos_cone, std::cos(40 * M_PI / 180), 1e-6);
  EXPECT_NEAR(dl[1].cos_falloff_start, std::cos(30 * M_PI / 180), 1e-6);
  EXPECT_EQ(dl[2].kind, DeltaLightDesc::Kind::Distant);
  expect_near(dl[2].direction, {0, -1, 0}, 1e-6f, "distant: travels from -> to");
  expect_near(dl[2].irradiance, {3, 3, 3}, 0, "distant L");
  expect_near(im.scene.environment.radiance, {0.5f, 0.5f, 0.5f}, 0, "infinite L");
  const Material& e = im.scene.materials[im.scene.shapes[0].material];
  EXPECT_EQ(e.type, MaterialType::Emitter);
  EXPECT_TRUE(e.two_sided);
  // A blackbody is normalised to luminance 1 (pbrt-v4's lights divide by its photometric
  // value), then scaled; 6500 K is close to white.
  EXPECT_NEAR(luminance(e.radiance), 4, 0.01);
  EXPECT_NEAR(e.radiance.x / e.radiance.z, 1, 0.1);
}

TEST(PbrtImport, BlackbodyAndSampledSpectraConvertToRgb) {
  // Warm below ~6500 K, cool above; luminance 1.
  const Vec3 warm = blackbody_rgb(2700), cool = blackbody_rgb(12000);
  EXPECT_GT(warm.x, warm.z);
  EXPECT_LT(cool.x, cool.z);
  EXPECT_NEAR(luminance(warm), 1, 0.01);
  // A constant reflectance spectrum is that grey; a flat emission spectrum has luminance 1.
  expect_near(sampled_spectrum_to_rgb({300, 0.4, 900, 0.4}, false), Vec3(0.4f), 1e-4f, "constant reflectance");
  EXPECT_NEAR(luminance(sampled_spectrum_to_rgb({300, 7, 900, 7}, true)), 1, 0.01);
  // The matching functions' fit: y-bar peaks near 555 nm at about 1.
  EXPECT_NEAR(cie_xyz_bar(555).y, 1, 0.02);
}

TEST(PbrtImport, NamedIlluminantsConvertFromTheirChromaticities) {
  // D65 is sRGB's white point: white at luminance 1. A is Planck's law at 2856 K.
  expect_near(*named_illuminant_rgb("stdillum-D65"), Vec3(1.0f), 2e-3f, "D65");
  expect_near(*named_illuminant_rgb("stdillum-A"), blackbody_rgb(2856), 0, "A");
  const Vec3 d50 = *named_illuminant_rgb("stdillum-D50"), f4 = *named_illuminant_rgb("stdillum-F4");
  EXPECT_GT(d50.x, d50.z);                // warmer than D65
  EXPECT_GT(f4.x / f4.z, d50.x / d50.z);  // warm white fluorescent, warmer still
  for (const char* n : {"stdillum-F1", "stdillum-F12", "illum-acesD60", "stdillum-D50"})
    EXPECT_NEAR(luminance(*named_illuminant_rgb(n)), 1, 1e-3) << n;
  EXPECT_FALSE(named_illuminant_rgb("stdillum-F13"));
  EXPECT_FALSE(named_illuminant_rgb("metal-Au-eta"));
  // Emission takes them; a reflectance does not (reported, default used).
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\nAreaLightSource \"diffuse\" \"spectrum L\" \"stdillum-D65\" \"float scale\" 2\n"
                         "Shape \"sphere\"\n");
  expect_near(im.scene.materials[size_t(im.scene.shapes[0].material)].radiance, Vec3(2.0f), 4e-3f,
              "scaled D65 emitter");
  PbrtImport r =
      import(std::string(kCamera) +
             "WorldBegin\nMaterial \"diffuse\" \"spectrum reflectance\" \"stdillum-D65\"\nShape \"sphere\"\n");
  ASSERT_EQ(r.report.size(), 1u);
  EXPECT_NE(r.report[0].find("named spectrum \"stdillum-D65\" for \"reflectance\" is not supported"),
            std::string::npos);
}

TEST(PbrtImport, WhatPdrtCannotRepresentIsReportedWithItsPosition) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "Shape \"curve\" \"point3 P\" [0 0 0 1 1 1 2 2 2 3 3 3]\n"
                         "Shape \"sphere\" \"float radius\" 1 \"float foo\" 2\n"
                         "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n");
  ASSERT_EQ(im.report.size(), 3u);
  EXPECT_EQ(im.report[0], "s.pbrt:4:1: Shape \"curve\" is not supported (skipped)");
  EXPECT_EQ(im.report[1], "s.pbrt:5:33: \"float foo\" is not used by pdrt (ignored)");
  EXPECT_EQ(im.report[2], "s.pbrt:6:1: MakeNamedMedium is not supported: pdrt has no participating media (ignored)");
  EXPECT_EQ(import_error(std::string(kCamera) + "WorldBegin\nShape \"curve\"\nShape \"sphere\"\n", true),
            "s.pbrt:4:1: Shape \"curve\" is not supported (skipped) [--strict]");
}

TEST(PbrtImport, ContradictoryInputIsRefusedWithItsPosition) {
  const std::string w = std::string(kCamera) + "WorldBegin\n";
  EXPECT_EQ(import_error(w + "Camera \"perspective\"\n"), "s.pbrt:4:1: a second Camera");
  EXPECT_EQ(import_error("WorldBegin\nCamera \"perspective\"\n"), "s.pbrt:2:1: Camera must come before WorldBegin");
  EXPECT_EQ(import_error(w + "AttributeEnd\n"), "s.pbrt:4:1: AttributeEnd without a matching AttributeBegin");
  EXPECT_EQ(import_error(w + "TransformBegin\nAttributeEnd\n"),
            "s.pbrt:5:1: AttributeEnd closes the TransformBegin at s.pbrt:4:1");
  EXPECT_EQ(import_error(w + "NamedMaterial \"nope\"\n"), "s.pbrt:4:1: unknown named material \"nope\"");
  EXPECT_EQ(import_error(w + "ObjectInstance \"nope\"\n"), "s.pbrt:4:1: unknown object \"nope\"");
  EXPECT_EQ(import_error(w + "CoordSysTransform \"nope\"\n"), "s.pbrt:4:1: unknown coordinate system \"nope\"");
  EXPECT_EQ(import_error("Integrator \"bdpt\"\n" + w + "Shape \"sphere\"\n"),
            "s.pbrt:1:1: Integrator \"bdpt\" is not supported: pdrt is a unidirectional path tracer (use \"path\" or "
            "\"volpath\")");
  EXPECT_EQ(import_error(w + "Shape \"sphere\" \"float radius\" -1\n"),
            "s.pbrt:4:16: \"float radius\" must be > 0, got -1");
  EXPECT_EQ(import_error(w + "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 3]\n"),
            "s.pbrt:4:53: index 3 is out of range [0, 2]");
  EXPECT_EQ(import_error(w + "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"normal N\" [0 0 1]\n"),
            "s.pbrt:4:53: \"N\" needs one normal per point (3), got 1");
  EXPECT_EQ(import_error(w + "Material \"diffuse\" \"rgb reflectance\" [1 2]\nShape \"sphere\"\n"),
            "s.pbrt:4:20: \"rgb reflectance\" needs 3 values, got 2");
  EXPECT_EQ(import_error(w), "s.pbrt:3:1: the scene has no shapes and no lights");
  EXPECT_EQ(import_error("Scale 0 0 0\n" + std::string(kCamera) + "WorldBegin\nShape \"sphere\"\n"),
            "s.pbrt:3:1: the camera transform is singular or projective");
}

TEST(PbrtImport, ObjectInstancesBecomePrototypesAndInstances) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "ObjectBegin \"ball\"\n"
                         "  Translate 0 1 0\n"
                         "  Shape \"sphere\" \"float radius\" 0.5\n"
                         "ObjectEnd\n"
                         "Translate 5 0 0\n"
                         "ObjectInstance \"ball\"\n"
                         "Translate 5 0 0\n"
                         "ObjectInstance \"ball\"\n");
  EXPECT_TRUE(im.scene.shapes.empty());
  ASSERT_EQ(im.scene.prototypes.size(), 1u);
  EXPECT_EQ(im.scene.prototypes[0].name, "ball");
  ASSERT_EQ(im.scene.prototypes[0].shapes.size(), 1u);
  ASSERT_EQ(im.scene.instances.size(), 2u);
  const ShapeDesc& ball = im.scene.prototypes[0].shapes[0];
  expect_near(ball.transform.point({0, 0, 0}), {0, 1, 0}, 1e-6f, "the ball within the object");
  for (int i = 0; i < 2; ++i) {
    const InstanceDesc& in = im.scene.instances[size_t(i)];
    EXPECT_EQ(in.prototype, 0);
    EXPECT_TRUE(in.motion.empty());
    expect_near((in.transform * ball.transform).point({0, 0, 0}), {5.0f * float(i + 1), 1, 0}, 1e-6f,
                "instance " + std::to_string(i));
  }
}

// pbrt-v4's BasicSceneBuilder: a shape inside ObjectBegin/End keeps the whole CTM at its
// definition (the CTM at ObjectBegin included), and the instance's CTM applies on top:
// world = CTM(ObjectInstance) * CTM(Shape).
TEST(PbrtImport, AnObjectDefinedUnderATransformKeepsItUnderTheInstances) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "AttributeBegin\n"
                         "  Translate 0 0 10\n"
                         "  Rotate 90 0 1 0\n"
                         "  ObjectBegin \"thing\"\n"
                         "    Scale 2 2 2\n"
                         "    Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n"
                         "  ObjectEnd\n"
                         "AttributeEnd\n"
                         "Translate 3 0 0\n"
                         "ObjectInstance \"thing\"\n");
  ASSERT_EQ(im.scene.instances.size(), 1u);
  const Affine world = im.scene.instances[0].transform * im.scene.prototypes[0].shapes[0].transform;
  // (1, 0, 0) -> scale 2 -> (2, 0, 0) -> Rotate 90 about y -> (0, 0, -2) -> +(0, 0, 10) -> +(3, 0, 0).
  expect_near(world.point({1, 0, 0}), {3, 0, 8}, 1e-5f, "x vertex");
  expect_near(world.point({0, 1, 0}), {3, 2, 10}, 1e-5f, "y vertex");
}

TEST(PbrtImport, AMovingObjectInstanceGetsMotionKeysAtTheTransformTimes) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "ObjectBegin \"ball\"\n"
                         "  Shape \"sphere\" \"float radius\" 0.5\n"
                         "ObjectEnd\n"
                         "ActiveTransform EndTime\n"
                         "Translate 2 0 0\n"
                         "ActiveTransform All\n"
                         "Translate 0 1 0\n"
                         "ObjectInstance \"ball\"\n");
  ASSERT_EQ(im.scene.instances.size(), 1u);
  const InstanceDesc& in = im.scene.instances[0];
  ASSERT_EQ(in.motion.size(), 2u);
  EXPECT_FLOAT_EQ(in.motion[0].time, 0);
  EXPECT_FLOAT_EQ(in.motion[1].time, 1);
  expect_near((in.motion[0].matrix() * in.transform).point({0, 0, 0}), {0, 1, 0}, 1e-6f, "start");
  expect_near((in.motion[1].matrix() * in.transform).point({0, 0, 0}), {2, 1, 0}, 1e-6f, "end");
}

TEST(PbrtImport, WhatObjectInstancesCannotHoldIsReported) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "ObjectBegin \"lamp\"\n"
                         "  AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                         "  Shape \"sphere\"\n"
                         "ObjectEnd\n"
                         "ObjectBegin \"nothing\"\n"
                         "  Shape \"curve\"\n"
                         "ObjectEnd\n"
                         "ObjectInstance \"lamp\"\n"
                         "ObjectInstance \"nothing\"\n");
  ASSERT_EQ(im.report.size(), 3u);
  EXPECT_EQ(im.report[0], "s.pbrt:6:3: area lights inside object definitions are not supported (no emission)");
  EXPECT_EQ(im.report[1], "s.pbrt:9:3: Shape \"curve\" is not supported (skipped)");
  EXPECT_EQ(im.report[2], "s.pbrt:12:1: object \"nothing\" has no shapes pdrt can render (instance skipped)");
  // The empty object is dropped; the lamp's sphere is a diffuse shape of one instance.
  ASSERT_EQ(im.scene.prototypes.size(), 1u);
  ASSERT_EQ(im.scene.instances.size(), 1u);
  EXPECT_EQ(im.scene.instances[0].prototype, 0);
  EXPECT_NE(im.scene.materials[size_t(im.scene.prototypes[0].shapes[0].material)].type, MaterialType::Emitter);
}

// A pbrt scene with instances renders the image of the SceneDesc a JSON file with the same
// prototypes and instances gives (identical descriptions: the same image bit for bit), and
// the scene with the shapes copied instead within the instancing tolerance (test_instances.cpp).
TEST(PbrtImport, ObjectInstancesRenderTheImageOfTheirJsonEquivalent) {
  PbrtImport im = import(kTwinHeader + kTwinLamp +
                         "Material \"diffuse\" \"rgb reflectance\" [0.6 0.5 0.4]\n"
                         "ObjectBegin \"ball\"\n"
                         "  Translate 0 0.5 0\n"
                         "  Shape \"sphere\" \"float radius\" 0.5\n"
                         "ObjectEnd\n"
                         "AttributeBegin\n"
                         "  Translate -0.8 0 0\n"
                         "  ObjectInstance \"ball\"\n"
                         "AttributeEnd\n"
                         "AttributeBegin\n"
                         "  Translate 0.8 0 0\n"
                         "  ObjectInstance \"ball\"\n"
                         "AttributeEnd\n");
  SceneDesc j = twin_scene();
  j.camera = im.scene.camera;
  add_twin_lamp(j);
  Material red = diffuse(0);
  red.albedo = {0.6f, 0.5f, 0.4f};
  PrototypeDesc ball;
  ball.shapes.push_back(sphere({0, 0, 0}, 0.5f, add_material(j, red)));
  ball.shapes[0].transform = Affine::translate({0, 0.5f, 0});
  j.prototypes.push_back(ball);
  for (float x : {-0.8f, 0.8f}) {
    InstanceDesc in;
    in.transform = Affine::translate({x, 0, 0});
    j.instances.push_back(in);
  }
  ASSERT_EQ(im.scene.prototypes.size(), 1u);
  ASSERT_EQ(im.scene.instances.size(), 2u);
  expect_renders_agree(im.scene, j);
}

TEST(PbrtImport, RendersTheImageOfItsJsonEquivalent) {
  // The same small scene written both ways: a pbrt file, and the SceneDesc a JSON file would
  // give. Identical descriptions render identical images (bit for bit: same floats).
  PbrtImport im = import(kTwinHeader + kTwinLamp +
                         "Material \"diffuse\" \"rgb reflectance\" [0.6 0.5 0.4]\n"
                         "Translate 0 0.5 0\n"
                         "Shape \"sphere\" \"float radius\" 0.5\n");
  SceneDesc j = twin_scene();
  j.film.filter.type = FilterType::Box;
  j.film.filter.radius = 0.5f;
  add_twin_lamp(j);
  Material red = diffuse(0);
  red.albedo = {0.6f, 0.5f, 0.4f};
  j.shapes.push_back(sphere({0, 0.5f, 0}, 0.5f, add_material(j, red)));

  SceneDesc& p = im.scene;
  // pbrt's up is the LookAt frame's, orthogonal to the view; pdrt orthogonalises its own the
  // same way, but not to the same last bit.
  EXPECT_NEAR(dot(p.camera.up, normalize(j.camera.look_at - j.camera.position)), 0, 1e-6);
  EXPECT_NEAR(dot(p.camera.up, Vec3(0, 1, 0)), std::cos(std::atan2(0.5, 6)), 1e-6);
  expect_renders_agree(p, j);
}

namespace {

std::filesystem::path ply_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("pdrt_ply_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void write_file(const std::filesystem::path& f, const std::string& bytes) {
  std::ofstream(f, std::ios::binary) << bytes;
}

// A unit quad (one face of 4 vertices) with normals and uv, in ASCII.
const char* kAsciiQuad =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\nproperty float u\nproperty float v\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n0 1 0 0 0 1 0 1\n4 0 1 2 3\n";

// The ASCII header of a triangle: three vertices (x, y, z) and one face whose list count is a
// count_type.
std::string ply_triangle_header(const std::string& count_type = "uchar") {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list " +
         count_type + " int vertex_indices\nend_header\n";
}
// The body that fills that header.
const char* kPlyTriangleBody = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

std::string binary_triangles(int n_tri, bool truncate) {
  std::string h = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(3 * n_tri) +
                  "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(n_tri) +
                  "\nproperty list uchar int vertex_indices\nend_header\n";
  std::string b;
  auto put = [&](const void* p, size_t n) { b.append(static_cast<const char*>(p), n); };
  for (int t = 0; t < n_tri; ++t) {
    float v[9] = {float(t), 0, 0, float(t) + 1, 0, 0, float(t), 1, 0};
    put(v, sizeof v);
  }
  for (int t = 0; t < n_tri; ++t) {
    unsigned char three = 3;
    int idx[3] = {3 * t, 3 * t + 1, 3 * t + 2};
    put(&three, 1);
    put(idx, sizeof idx);
  }
  if (truncate) b.resize(b.size() - 7);
  return h + b;
}

}  // namespace

TEST(PbrtImport, PlyMeshesLoadAsciiAndBinaryWithQuadsAndNormals) {
  const std::filesystem::path dir = ply_dir();
  write_file(dir / "quad.ply", kAsciiQuad);
  write_file(dir / "tris.ply", binary_triangles(5, false));
  write_file(dir / "s.pbrt", std::string(kCamera) +
                                 "WorldBegin\nShape \"plymesh\" \"string filename\" \"quad.ply\"\n"
                                 "Translate 0 0 1\nShape \"plymesh\" \"string filename\" \"tris.ply\"\n");
  PbrtImport im = load_pbrt_scene(dir / "s.pbrt", false);
  ASSERT_EQ(im.scene.shapes.size(), 2u);
  const MeshData& q = im.scene.shapes[0].mesh;
  EXPECT_EQ(q.positions.size(), 4u);
  EXPECT_EQ(q.indices.size(), 6u);  // the quad, triangulated
  ASSERT_EQ(q.normals.size(), 4u);
  expect_near(q.normals[2], {0, 0, 1}, 0, "normal");
  // Each triangle winds counter-clockwise about the normals' side (+z).
  for (size_t i = 0; i < q.indices.size(); i += 3) {
    const Vec3 ng = cross(q.positions[q.indices[i + 1]] - q.positions[q.indices[i]],
                          q.positions[q.indices[i + 2]] - q.positions[q.indices[i]]);
    EXPECT_GT(ng.z, 0);
  }
  const MeshData& t = im.scene.shapes[1].mesh;
  EXPECT_EQ(t.positions.size(), 15u);
  EXPECT_EQ(t.indices.size(), 15u);
  expect_near(t.positions[4], {2, 0, 0}, 0, "binary vertex 4");
  expect_near(im.scene.shapes[1].transform.point(t.positions[4]), {2, 0, 1}, 0, "placed");
  std::filesystem::remove_all(dir);
}

TEST(PbrtImport, BadPlyFilesAreRefusedNamingTheShapeAndThePlace) {
  const std::filesystem::path dir = ply_dir();
  struct Case {
    const char* name;
    std::string bytes;
    std::string what;  // after "<s.pbrt>:4:17: <dir>/<name>"
  };
  const std::string tri = ply_triangle_header();
  const std::string full = binary_triangles(4, false);
  const Case cases[] = {
      {"keyword.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_heade\n",
       ":5:1: unknown PLY header keyword \"end_heade\""},
      {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
       ":4:1: the PLY header has no end_header"},
      {"magic.ply", "plx\n", ":1:1: not a PLY file (the first line must be \"ply\")"},
      {"format.ply", "ply\nformat binary 1.0\nend_header\n",
       ":2:8: unknown PLY format \"binary\" (ascii, binary_little_endian, binary_big_endian)"},
      {"type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n",
       ":4:10: unknown PLY type \"real\""},
      {"ascii_short.ply", tri + "0 0 0\n1 0 0\n", ":12:1: the body ends at vertex 2 of 3 (truncated)"},
      {"ascii_nan.ply", tri + "0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n",
       ":11:3: \"x\" is not a number (digits, a point, digits, an exponent)"},
      {"ascii_long.ply", tri + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 7\n", ":13:9: face 0 has more values than its properties"},
      {"short.ply", binary_triangles(4, true),
       ": byte " + std::to_string(full.size() - 7) + ": the body ends inside face 3 of 4 (truncated)"},
      {"trailing.ply", full + "xyz", ": byte " + std::to_string(full.size()) + ": 3 bytes after the last element"},
  };
  for (const Case& c : cases) {
    write_file(dir / c.name, c.bytes);
    write_file(dir / "s.pbrt",
               std::string(kCamera) + "WorldBegin\nShape \"plymesh\" \"string filename\" \"" + c.name + "\"\n");
    EXPECT_EQ(file_import_error(dir / "s.pbrt"),
              (dir / "s.pbrt").string() + ":4:17: " + (dir / c.name).string() + c.what)
        << c.name;
  }
  write_file(dir / "s.pbrt",
             std::string(kCamera) + "WorldBegin\nShape \"plymesh\" \"string filename\" \"missing.ply\"\n");
  EXPECT_EQ(file_import_error(dir / "s.pbrt"), (dir / "s.pbrt").string() + ":4:17: " + (dir / "missing.ply").string() +
                                                   ": cannot open: No such file or directory");
  std::filesystem::remove_all(dir);
}

// Found with tests/fuzz/fuzz_ply.cpp: an ASCII list count of 2^64 or more is refused like any
// count that is not an integer of its type (its conversion to an integer was undefined).
TEST(PbrtImport, PlyListCountBeyondEveryIntegerIsRefused) {
  const std::filesystem::path dir = ply_dir();
  write_file(dir / "big.ply", ply_triangle_header() + "0 0 0\n1 0 0\n0 1 0\n1e30 0 1 2\n");
  write_file(dir / "s.pbrt", std::string(kCamera) + "WorldBegin\nShape \"plymesh\" \"string filename\" \"big.ply\"\n");
  EXPECT_EQ(file_import_error(dir / "s.pbrt"), (dir / "s.pbrt").string() + ":4:17: " + (dir / "big.ply").string() +
                                                   ":13:1: \"1e30\" is not a uchar (an integer)");
  std::filesystem::remove_all(dir);
}

// Found by the CI run of tests/fuzz/fuzz_ply.cpp (the input as found, minimised): a coordinate of
// 21 digits overflowed Assimp 5.2's integer reader, which left its digits to be read as the list
// count that followed and allocated 20 GB. The check refuses it first.
TEST(PbrtImport, PlyCoordinateOfTwentyDigitsIsRefusedBeforeAssimpReadsIt) {
  const std::filesystem::path file =
      std::filesystem::path(PDRT_TEST_DATA_DIR) / "fuzz" / "ply" / "oom-20-digit-coordinate-before-a-list.ply";
  EXPECT_EQ(ply_error(file, "oom.ply"),
            "oom.ply:10:3: \"666666666666666666660\" has more than 19 digits before its point");
}

// Found by the long run of tests/fuzz/fuzz_ply.cpp (the inputs as found; the second minimised):
// Assimp 5.2 reads the count of an element with another name than vertex, face, tristrips, edge
// or material from the digits its name starts with, so such an element with instances shifted
// every later line (an abort, allocations of 30 to 100 GB); after the last element with
// instances it is harmless and still loads.
TEST(PbrtImport, PlyElementsAssimpWouldMiscountAreRefused) {
  const std::filesystem::path data = std::filesystem::path(PDRT_TEST_DATA_DIR) / "fuzz" / "ply";
  // The first input, as found, is now refused earlier, for the words past its header lines' fields.
  EXPECT_EQ(ply_error(data / "oom-element-name-of-digits.ply", "t.ply").rfind("t.ply:", 0), 0u);
  EXPECT_EQ(ply_error(data / "oom-unknown-element-before-vertex.ply", "t.ply"),
            "t.ply:3:1: element \"cma\" has instances before element \"vertex\", which Assimp 5.2 (pdrt's PLY "
            "reader) would misread: only vertex, face, tristrips, edge and material elements may come first");
  const std::filesystem::path dir = ply_dir();
  // Its minimised form took Assimp 29 s for a count of 9999999 read from the name.
  write_file(dir / "digits.ply", "ply\nformat ascii 1.0\nelement 9999999 0\nend_header\n");
  EXPECT_EQ(ply_error(dir / "digits.ply", "t.ply"),
            "t.ply:3:9: an element name must not start with a digit, got \"9999999\"");
  write_file(dir / "after.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "element face 1\nproperty list uchar int vertex_indices\nelement cma 2\nproperty float a\n"
             "element empty 0\nproperty float b\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n5\n6\n");
  EXPECT_EQ(load_ply(dir / "after.ply", "after.ply").mesh.indices.size(), 3u);
  std::filesystem::remove_all(dir);
}

// Found by the long run of tests/fuzz/fuzz_ply.cpp (the input as found): Assimp 5.2 looped
// forever on a header whose element name held a byte 0xa0 and whose end_header had no line feed.
// PLY headers are ASCII lines: either fault alone is refused.
TEST(PbrtImport, PlyHeaderNotAsciiOrWithoutItsLastLineFeedIsRefused) {
  const std::filesystem::path data = std::filesystem::path(PDRT_TEST_DATA_DIR) / "fuzz" / "ply";
  EXPECT_EQ(ply_error(data / "hang-non-ascii-name-no-line-feed.ply", "t.ply"),
            "t.ply:3:10: a byte that is not ASCII (0xa0) in the PLY header");
  const std::filesystem::path dir = ply_dir();
  std::string tri = ply_triangle_header();
  tri.pop_back();  // end_header's line feed
  write_file(dir / "nolf.ply", tri);
  EXPECT_EQ(ply_error(dir / "nolf.ply", "nolf.ply"), "nolf.ply:9:11: end_header must end with a line feed");
  write_file(dir / "crlf.ply", tri + "\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n");
  EXPECT_EQ(load_ply(dir / "crlf.ply", "crlf.ply").mesh.indices.size(), 3u);
  std::filesystem::remove_all(dir);
}

// Assimp 5.2 reads a line of spaces or tabs in an ASCII body, or the second of two empty lines,
// as an element, and every later line as the one before it: with this face after the vertices it
// aborted on an empty face. Every blank line in the body is refused; after the body it is harmless.
TEST(PbrtImport, PlyBodyWithABlankLineIsRefused) {
  const std::filesystem::path dir = ply_dir();
  const std::string head = ply_triangle_header("uint");
  for (const char* blank : {"", " ", "\t", "\r"}) {
    write_file(dir / "b.ply", head + "0 0 0\n" + blank + "\n1 0 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(ply_error(dir / "b.ply", "b.ply"),
              "b.ply:11:1: a blank line in the PLY body, where every line is one vertex")
        << "blank line \"" << blank << "\"";
  }
  write_file(dir / "after.ply", head + kPlyTriangleBody + "  \n\n");
  EXPECT_EQ(load_ply(dir / "after.ply", "after.ply").mesh.indices.size(), 3u);
  std::filesystem::remove_all(dir);
}

// Assimp 5.2 reads the format from the second line where pdrt's check took the last format line
// (a binary body read as ASCII crashed it), and reads some words past a header line's fields (an
// unknown element's name runs to the last space): a format elsewhere, a second one and extra
// words are refused.
TEST(PbrtImport, PlyHeaderLinesFollowPlysGrammar) {
  const std::filesystem::path dir = ply_dir();
  // The triangle's header past its format line, and its body.
  const std::string body =
      ply_triangle_header().substr(std::string("ply\nformat ascii 1.0\n").size()) + kPlyTriangleBody;
  const std::pair<std::string, std::string> cases[] = {
      {"ply\nformat binary_little_endian 1.0\nformat ascii 1.0\n" + body, "3:1: a second format line"},
      {"ply\nformat ascii 1.0 x\n" + body,
       "2:18: \"x\" after the line's fields: a format line is \"format <format> 1.0\""},
      {"ply\nformat ascii 1.0\nelement cma 0 ply\n" + body,
       "3:15: \"ply\" after the line's fields: an element line is \"element <name> <count>\""},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x y\n",
       "4:18: \"y\" after the line's fields: a property is \"property <type> <name>\""},
      {"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices x\n",
       "4:40: \"x\" after the line's fields: a list property is \"property list <count type> <type> <name>\""},
  };
  for (const auto& [text, error] : cases) {
    write_file(dir / "h.ply", text);
    EXPECT_EQ(ply_error(dir / "h.ply", "h.ply"), "h.ply:" + error);
  }
  write_file(dir / "late.ply", "ply\ncomment made by hand\nformat ascii 1.0\n" + body);
  EXPECT_EQ(ply_error(dir / "late.ply", "h.ply"), "h.ply:2:1: the second line must be \"format <format> 1.0\"");
  write_file(dir / "ok.ply", "ply\nformat ascii 1.0\ncomment made by hand\nobj_info x y z\n" + body);
  EXPECT_EQ(load_ply(dir / "ok.ply", "ok.ply").mesh.indices.size(), 3u);
  std::filesystem::remove_all(dir);
}

// Assimp 5.2 reads an ASCII value by its property's type and reads the rest of a token as the
// next value, so a token it would read only in part (a fraction for an int, a sign for an
// unsigned type, a hexadecimal float) is refused where it stands; the forms it reads whole pass.
TEST(PbrtImport, PlyAsciiValuesAssimpWouldReadInPartAreRefused) {
  const std::filesystem::path dir = ply_dir();
  const std::string head = ply_triangle_header();
  auto body = [](const std::string& y, const std::string& face) {
    return "0 0 0\n1 " + y + " 0\n0 1 0\n" + face + "\n";
  };
  struct Case {
    std::string y, face, error;  // error "" when the file loads
  };
  const Case cases[] = {
      {"0", "3 0 1 2", ""},
      {"-0.", "3 0 1 2", ""},
      {"+.5e-3", "3 0 1 2", ""},
      {"1E+5", "3 0 1 2", ""},
      {"0000000000000000000001.5", "3 0 1 2", ""},
      {"9999999999999999999", "3 0 1 2", ""},
      {"0x1p3", "3 0 1 2", "11:3: \"0x1p3\" is not a number (digits, a point, digits, an exponent)"},
      {".", "3 0 1 2", "11:3: \".\" is not a number (digits, a point, digits, an exponent)"},
      {"1e", "3 0 1 2", "11:3: \"1e\" is not a number (digits, a point, digits, an exponent)"},
      {"1e10000000000000000000", "3 0 1 2", "11:3: \"1e10000000000000000000\" has an exponent of more than 19 digits"},
      {"0", "3 0 1.5 2", "13:5: \"1.5\" is not a int (an integer)"},
      {"0", "-3 0 1 2", "13:1: \"-3\" is not a uchar (an integer)"},
      {"0", "+3 0 1 2", "13:1: \"+3\" is not a uchar (an integer)"},
      {"0", "300 0 1 2", "13:1: \"300\" is out of range for a uchar (0 to 255)"},
      {"0", "3 0 1 2147483648", "13:7: \"2147483648\" is out of range for a int (-2147483648 to 2147483647)"},
  };
  for (const Case& c : cases) {
    write_file(dir / "v.ply", head + body(c.y, c.face));
    if (c.error.empty()) {
      EXPECT_NO_THROW(load_ply(dir / "v.ply", "v.ply")) << c.y << " / " << c.face;
      continue;
    }
    EXPECT_EQ(ply_error(dir / "v.ply", "v.ply"), "v.ply:" + c.error) << c.y << " / " << c.face;
  }
  std::filesystem::remove_all(dir);
}

// Found with tests/fuzz/fuzz_ply.cpp (the inputs as found): NULs and vertical tabs in a PLY
// header or ASCII body made Assimp 5.2 crash, leak or loop forever; the check refuses them first.
TEST(PbrtImport, PlyTextWithControlCharactersIsRefusedBeforeAssimpReadsIt) {
  const std::filesystem::path dir = std::filesystem::path(PDRT_TEST_DATA_DIR) / "fuzz" / "ply";
  for (const char* name : {"segv-nul-in-header.ply", "leak-nul-in-body.ply", "hang-vtab-before-end-header.ply",
                           "hang-vtab-after-end-header.ply"}) {
    EXPECT_NE(ply_error(dir / name, name).find("a control character (byte 0x"), std::string::npos) << name;
  }
}

// Found by the ctest run of tests/fuzz/fuzz_ply.cpp (the input as found): a face with an empty
// index list made Assimp 5.2 abort on an assertion; the check refuses it first.
TEST(PbrtImport, PlyFaceWithoutVerticesIsRefusedBeforeAssimpReadsIt) {
  const std::filesystem::path file =
      std::filesystem::path(PDRT_TEST_DATA_DIR) / "fuzz" / "ply" / "abort-empty-face.ply";
  EXPECT_NE(ply_error(file, "abort-empty-face.ply").find("face 0 has an empty list"), std::string::npos);
}

// Found by the ctest run of tests/fuzz/fuzz_ply.cpp (the input as found): a quad with the index
// -3 crashed Assimp 5.2's triangulation, which read out of bounds; its validation, which runs
// first, refuses any index out of range, negative or past the vertices, in text or binary.
TEST(PbrtImport, PlyFaceWithAnIndexOutOfRangeIsRefused) {
  const std::filesystem::path file =
      std::filesystem::path(PDRT_TEST_DATA_DIR) / "fuzz" / "ply" / "segv-negative-index-in-a-quad.ply";
  const std::string e = ply_error(file, "q.ply");
  EXPECT_EQ(e.rfind("q.ply: cannot read the PLY mesh: ", 0), 0u) << e;
  const std::filesystem::path dir = ply_dir();
  write_file(dir / "past.ply", ply_triangle_header() + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_EQ(ply_error(dir / "past.ply", "past.ply").rfind("past.ply: cannot read the PLY mesh: ", 0), 0u);
  std::filesystem::remove_all(dir);
}

// Found by the long run of tests/fuzz/fuzz_pbrt.cpp (the input as found): one triangle at
// levels 12 asked for 4^12 triangles, 4.8 GB and 40 s of refinement for three lines of text.
TEST(PbrtImport, LoopSubdivBeyondTheTriangleLimitIsRefusedBeforeRefining) {
  const std::string e = fuzz_pbrt_error("oom-loopsubdiv-levels-12.pbrt");
  EXPECT_NE(e.find("oom-loopsubdiv-levels-12.pbrt:3:1: Shape \"loopsubdiv\": 1 triangles subdivided 12 times exceed "
                   "4194304 triangles"),
            std::string::npos)
      << e;
  // A lower limit, as the fuzzer sets it, refuses a smaller mesh; the default takes it.
  const std::string one = std::string(kCamera) +
                          "WorldBegin\nShape \"loopsubdiv\" \"integer levels\" 2 \"point3 P\" [0 0 0  1 0 0  0 1 0] "
                          "\"integer indices\" [0 1 2]\n";
  PbrtLimits limits;
  limits.max_subdivided_triangles = 15;
  EXPECT_THROW(build_pbrt_scene(parse_pbrt_text(one, "s.pbrt", "."), false, limits), InputError);
  EXPECT_EQ(import(one).scene.shapes.at(0).mesh.indices.size(), 3u * 16);
}

// Found by ctest's bounded run of tests/fuzz/fuzz_pbrt.cpp (the input as found): a second Film
// kept the first one's pixelbounds crop, made for 1280 x 720, which covers no pixel of its 32 x
// 24; the check that says so named the crop parameter of the second Film, which has none (a
// null pointer). Each Film now starts from the whole frame, as pbrt-v4's replaces the film, so
// the file reads on to its real error.
TEST(PbrtImport, ASecondFilmDoesNotKeepTheFirstFilmsCrop) {
  const std::string e = fuzz_pbrt_error("ubsan-second-film-keeps-first-crop.pbrt");
  EXPECT_NE(e.find("ubsan-second-film-keeps-first-crop.pbrt:9:1: a second WorldBegin"), std::string::npos) << e;
  const PbrtImport two = import(std::string(kCamera) +
                                "Film \"rgb\" \"integer xresolution\" 200 \"integer yresolution\" 100 "
                                "\"integer pixelbounds\" [10 20 5 15]\nFilm \"rgb\" \"integer xresolution\" 40 "
                                "\"integer yresolution\" 30\nWorldBegin\nShape \"sphere\"\n");
  EXPECT_EQ(two.scene.film.width, 40);
  EXPECT_EQ(two.scene.film.crop_window, (std::array<float, 4>{0, 1, 0, 1}));
}

// Found by the long run of tests/fuzz/fuzz_pbrt.cpp (the input as found): a bilinear patch with
// a coordinate beyond float's range made the grid size NaN, and converting it to int was
// undefined. Non-finite corners are refused before tessellating; corners so far apart that the
// twist overflows float take the largest grid.
TEST(PbrtImport, BilinearPatchWithAnInfiniteOrOverflowingCornerIsRefusedOrCapped) {
  const std::string e = fuzz_pbrt_error("ubsan-bilinear-infinite-coordinate.pbrt");
  EXPECT_NE(e.find("ubsan-bilinear-infinite-coordinate.pbrt:3:22: \"P\" holds a non-finite coordinate"),
            std::string::npos)
      << e;
  const PbrtImport im =
      import(std::string(kCamera) +
             "WorldBegin\nShape \"bilinearmesh\" \"point3 P\" [-3e38 -3e38 0  3e38 -3e38 0  -3e38 3e38 0  "
             "3e38 3e38 1e38]\n");
  bool capped = false;
  for (const std::string& line : im.report)
    capped = capped || line.find("twisted beyond a 64 x 64 grid") != std::string::npos;
  EXPECT_TRUE(capped);
  for (const Vec3& p : im.scene.shapes.at(0).mesh.positions) ASSERT_TRUE(is_finite(p));
}

TEST(PbrtImport, ReportsAKindOnceWithTheCountAndLastPlaceOfTheRest) {
  const PbrtImport im = import(std::string(kCamera) +
                               "WorldBegin\n"
                               "Material \"diffuse\" \"rgb reflectance\" [0.8 0.1 0.1]\n"
                               "Shape \"sphere\" \"float foo\" 1\n"
                               "Material \"diffuse\" \"rgb reflectance\" [0.1 0.8 0.1]\n"
                               "Shape \"sphere\" \"float foo\" 1\n"
                               "Material \"diffuse\" \"rgb reflectance\" [0.1 0.1 0.8]\n");
  ASSERT_EQ(im.report.size(), 2u);
  EXPECT_EQ(im.report[0],
            "s.pbrt:4:20: \"rgb reflectance\" (0.8, 0.1, 0.1 in linear sRGB) is not grey: pdrt multiplies colours per "
            "RGB channel where pbrt-v4 works per wavelength, so light it reflects differs in colour (by a few % for "
            "saturated colours; grey is exact) (and 2 more like it, the last at s.pbrt:8:20)");
  // The same message twice is one kind too.
  EXPECT_EQ(im.report[1],
            "s.pbrt:5:16: \"float foo\" is not used by pdrt (ignored) (and 1 more like it, the last at "
            "s.pbrt:7:16)");
}

TEST(PbrtImport, GreyColoursAndColouredEmissionRenderAsPbrtsAndAreNotReported) {
  const PbrtImport im = import(std::string(kCamera) +
                               "WorldBegin\n"
                               "LightSource \"point\" \"rgb I\" [1 0.5 0.2]\n"
                               "Material \"diffuse\" \"rgb reflectance\" [0.3 0.3 0.3]\n"
                               "Shape \"sphere\"\n"
                               "Material \"conductor\" \"float eta\" 1.5 \"float k\" 2\n"
                               "Shape \"sphere\"\n");
  EXPECT_TRUE(im.report.empty()) << im.report[0];
}

TEST(PbrtImport, EmitterMaterialIsReportedUnlessItIsBlack) {
  const std::string reflecting = std::string(kCamera) +
                                 "WorldBegin\n"
                                 "AttributeBegin\n"
                                 "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                                 "Shape \"sphere\"\n"
                                 "AttributeEnd\n";
  const PbrtImport im = import(reflecting);
  ASSERT_EQ(im.report.size(), 1u);
  EXPECT_EQ(im.report[0],
            "s.pbrt:6:1: an area light's shape only emits in pdrt; in pbrt-v4 its material (the default diffuse 0.5) "
            "also reflects the scene's light, so pbrt-v4's emitter is brighter by that");
  const PbrtImport black = import(std::string(kCamera) +
                                  "WorldBegin\n"
                                  "AttributeBegin\n"
                                  "Material \"diffuse\" \"rgb reflectance\" [0 0 0]\n"
                                  "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
                                  "Shape \"sphere\"\n"
                                  "AttributeEnd\n");
  EXPECT_TRUE(black.report.empty()) << black.report[0];
  EXPECT_EQ(import_error(reflecting, true), im.report[0] + " [--strict]");
}

TEST(PbrtImport, StrictRefusesColoursThatRenderDifferentlyInRgb) {
  EXPECT_EQ(import_error(std::string(kCamera) +
                             "WorldBegin\n"
                             "Material \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\"\n"
                             "Shape \"sphere\"\n",
                         true),
            "s.pbrt:4:22: named spectrum \"metal-Au-eta\" as three RGB values: pdrt multiplies colours per RGB channel "
            "where pbrt-v4 works per wavelength, so light it reflects differs in colour (by a few % for saturated "
            "colours; grey is exact) [--strict]");
}

TEST(PbrtImport, CoatedDiffuseMapsOntoTheLayeredModel) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "Material \"coateddiffuse\" \"rgb reflectance\" [0.2 0.4 0.6] \"float roughness\" 0.04 "
                         "\"float eta\" 1.4 \"float thickness\" 0.1 \"rgb albedo\" [0.5 0.6 0.7] \"float g\" -0.3 "
                         "\"integer maxdepth\" 7 \"integer nsamples\" 3\n"
                         "Shape \"sphere\"\n"
                         "Material \"coateddiffuse\"\n"
                         "Shape \"sphere\"\n");
  const Material& a = im.scene.materials[im.scene.shapes[0].material];
  EXPECT_EQ(a.type, MaterialType::CoatedDiffuse);
  EXPECT_TRUE(a.layered);
  expect_near(a.albedo, {0.2f, 0.4f, 0.6f}, 0, "reflectance");
  EXPECT_NEAR(a.roughness, std::sqrt(0.2), 1e-6);  // alpha = sqrt(0.04) = 0.2
  EXPECT_FLOAT_EQ(a.ior, 1.4f);
  EXPECT_FLOAT_EQ(a.layers.thickness, 0.1f);
  expect_near(a.layers.albedo, {0.5f, 0.6f, 0.7f}, 0, "the medium's albedo");
  EXPECT_FLOAT_EQ(a.layers.g, -0.3f);
  EXPECT_EQ(a.layers.max_depth, 7);
  EXPECT_EQ(a.layers.samples, 3);
  const Material& b = im.scene.materials[im.scene.shapes[1].material];  // pbrt-v4's defaults
  EXPECT_TRUE(b.layered);
  expect_near(b.albedo, Vec3(0.5f), 0, "default reflectance");
  EXPECT_EQ(b.roughness, 0);
  EXPECT_FLOAT_EQ(b.ior, 1.5f);
  EXPECT_FLOAT_EQ(b.layers.thickness, 0.01f);
  expect_near(b.layers.albedo, Vec3(0.0f), 0, "default albedo");
  EXPECT_EQ(b.layers.g, 0.0f);
  EXPECT_EQ(b.layers.max_depth, 10);
  EXPECT_EQ(b.layers.samples, 1);
  EXPECT_TRUE(report_besides_rgb(im.report).empty());
  EXPECT_NE(im.report[0].find("s.pbrt:4:26: \"rgb reflectance\" (0.2, 0.4, 0.6 in linear sRGB) is not grey"),
            std::string::npos)
      << im.report[0];
}

TEST(PbrtImport, CoatedConductorMapsOntoTheLayeredModel) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "Material \"coatedconductor\" \"float interface.roughness\" 0.01 \"float interface.eta\" 1.3 "
                         "\"spectrum conductor.eta\" \"metal-Au-eta\" \"spectrum conductor.k\" \"metal-Au-k\" "
                         "\"float conductor.roughness\" 0.16 \"float thickness\" 0.2 \"integer maxdepth\" 4\n"
                         "Shape \"sphere\"\n"
                         "Material \"coatedconductor\" \"rgb reflectance\" [0.9 0.5 0.2] \"bool remaproughness\" false "
                         "\"float conductor.roughness\" 0.25\n"
                         "Shape \"sphere\"\n"
                         "Material \"coatedconductor\"\n"
                         "Shape \"sphere\"\n");
  const Material& a = im.scene.materials[im.scene.shapes[0].material];
  EXPECT_EQ(a.type, MaterialType::CoatedConductor);
  EXPECT_NEAR(a.roughness, std::sqrt(0.1), 1e-6);       // alpha = sqrt(0.01)
  EXPECT_NEAR(a.base_roughness, std::sqrt(0.4), 1e-6);  // alpha = sqrt(0.16)
  EXPECT_FLOAT_EQ(a.ior, 1.3f);
  expect_near(a.eta, find_named_metal("Au")->eta, 0, "gold's eta");
  expect_near(a.k, find_named_metal("Au")->k, 0, "gold's k");
  EXPECT_FLOAT_EQ(a.layers.thickness, 0.2f);
  EXPECT_EQ(a.layers.max_depth, 4);
  const Material& b = im.scene.materials[im.scene.shapes[1].material];
  expect_near(b.eta, Vec3(1.0f), 0, "reflectance: eta 1");
  EXPECT_NEAR(b.k[0], 2 * std::sqrt(0.9) / std::sqrt(0.1), 1e-4);
  EXPECT_NEAR(b.base_roughness, 0.5, 1e-6);                             // alpha 0.25 unremapped
  const Material& c = im.scene.materials[im.scene.shapes[2].material];  // pbrt-v4's defaults: copper
  expect_near(c.eta, find_named_metal("Cu")->eta, 0, "copper's eta");
  EXPECT_EQ(c.roughness, 0);
  EXPECT_EQ(c.base_roughness, 0);
  EXPECT_FLOAT_EQ(c.ior, 1.5f);
  EXPECT_FLOAT_EQ(c.layers.thickness, 0.01f);
  EXPECT_TRUE(report_besides_rgb(im.report).empty());  // the metals' spectra as RGB
}

TEST(PbrtImport, BadLayeredParametersAreRefusedWithTheirPosition) {
  const std::string w = std::string(kCamera) + "WorldBegin\n";
  EXPECT_EQ(import_error(w + "Material \"coateddiffuse\" \"float thickness\" -1\n"),
            "s.pbrt:4:26: \"float thickness\" must be >= 0, got -1");
  EXPECT_EQ(import_error(w + "Material \"coateddiffuse\" \"integer maxdepth\" -2\n"),
            "s.pbrt:4:26: \"integer maxdepth\" must be in [0, 1000], got -2");
  EXPECT_EQ(import_error(w + "Material \"coatedconductor\" \"integer nsamples\" 0\n"),
            "s.pbrt:4:28: \"integer nsamples\" must be in [1, 256], got 0");
  EXPECT_EQ(import_error(w + "Material \"coatedconductor\" \"float interface.eta\" 0\n"),
            "s.pbrt:4:28: \"float interface.eta\" must be > 0, got 0");
  EXPECT_EQ(import_error(w + "Material \"coatedconductor\" \"float conductor.roughness\" -0.5\n"),
            "s.pbrt:4:28: \"float conductor.roughness\" must be >= 0, got -0.5");
  EXPECT_EQ(import_error(w + "Material \"coatedconductor\" \"rgb reflectance\" [0.5 0.5 0.5] "
                             "\"rgb conductor.eta\" [1 1 1]\n"),
            "s.pbrt:4:28: \"reflectance\" cannot be given with \"conductor.eta\" (pbrt-v4 refuses both)");
}

TEST(PbrtImport, TexturesMapOntoPdrtsAndBindToReflectance) {
  const std::filesystem::path dir = ply_dir();
  write_file(dir / "wood.png", "not read while loading");
  write_file(
      dir / "s.pbrt",
      std::string(kCamera) +
          "WorldBegin\n"
          "Texture \"grain\" \"spectrum\" \"imagemap\" \"string filename\" \"wood.png\" \"string filter\" \"point\""
          " \"string wrap\" \"clamp\" \"string encoding\" \"linear\" \"float uscale\" 4\n"
          "Texture \"checks\" \"spectrum\" \"checkerboard\" \"texture tex1\" \"grain\" \"rgb tex2\" [0.1 0.2 0.3]"
          " \"float uscale\" 8 \"float vscale\" 2\n"
          "Texture \"noise\" \"float\" \"fbm\"\n"
          "Material \"diffuse\" \"texture reflectance\" \"checks\"\n"
          "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"point2 uv\" [0 0 1 0 0 1]\n"
          "Material \"coateddiffuse\" \"texture reflectance\" \"noise\"\n"
          "Shape \"sphere\"\n");
  PbrtImport im = load_pbrt_scene(dir / "s.pbrt", false);
  const auto& tx = im.scene.textures;
  ASSERT_EQ(tx.size(), 2u);
  EXPECT_EQ(tx[0].kind, TextureDesc::Kind::Image);
  EXPECT_EQ(tx[0].file, dir / "wood.png");
  EXPECT_EQ(tx[0].filter, TextureFilter::None);
  EXPECT_EQ(tx[0].wrap, TextureWrap::Clamp);
  EXPECT_EQ(tx[0].encoding, TextureEncoding::Linear);
  EXPECT_EQ(tx[0].scale_u, 4);
  EXPECT_EQ(tx[1].kind, TextureDesc::Kind::Checkerboard);
  EXPECT_EQ(tx[1].color0.texture, 0);
  expect_near(tx[1].color1.value, {0.1f, 0.2f, 0.3f}, 0, "tex2");
  EXPECT_EQ(tx[1].scale_u, 8);
  EXPECT_EQ(tx[1].scale_v, 2);
  const Material& m = im.scene.materials[im.scene.shapes[0].material];
  ASSERT_EQ(m.textures.size(), 1u);
  EXPECT_EQ(m.textures[0].param, MaterialParam::Albedo);
  EXPECT_EQ(m.textures[0].texture, 1);
  ASSERT_EQ(im.scene.shapes[0].mesh.uvs.size(), 3u);
  EXPECT_EQ(im.scene.shapes[0].mesh.uvs[1][0], 1);
  // The unsupported fbm texture is reported where it is defined and where it is used.
  const std::vector<std::string> report = report_besides_rgb(im.report);
  ASSERT_EQ(report.size(), 2u);
  EXPECT_NE(report[0].find(":6:1: Texture class \"fbm\" is not supported"), std::string::npos) << report[0];
  EXPECT_NE(report[1].find(":9:26: texture \"noise\" is not supported"), std::string::npos) << report[1];
  EXPECT_TRUE(im.scene.materials[im.scene.shapes[1].material].textures.empty());
  write_file(
      dir / "t.pbrt",
      std::string(kCamera) + "WorldBegin\nMaterial \"diffuse\" \"texture reflectance\" \"nope\"\nShape \"sphere\"\n");
  EXPECT_EQ(file_import_error(dir / "t.pbrt"), (dir / "t.pbrt").string() + ":4:20: unknown texture \"nope\"");
  std::filesystem::remove_all(dir);
}

// Motion blur through ActiveTransform: a small two-sided emitter moved by the end-time
// transform, and a camera moved the same way, render the streaks of the equivalent JSON scene
// (motion keys at the TransformTimes): the object's streak bit for bit (its keys decompose
// exactly), the moving camera's within 1e-3 of the image mean per pixel on average (its view
// direction goes through a matrix inverse).
TEST(PbrtImport, ActiveTransformRendersTheStreakOfTheJsonMotionKeys) {
  const std::string head =
      "LookAt 0 0 -5  0 0 0  0 1 0\n"
      "Camera \"perspective\" \"float fov\" 30\n"
      "Film \"rgb\" \"integer xresolution\" 48 \"integer yresolution\" 32\n"
      "Sampler \"independent\" \"integer pixelsamples\" 16\n"
      "PixelFilter \"box\"\n"
      "WorldBegin\n";
  const std::string light =
      "AttributeBegin\n"
      "  AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
      "  ActiveTransform EndTime\n  Translate 1 0 0\n  ActiveTransform All\n"
      "  Shape \"trianglemesh\" \"point3 P\" [-0.3 -0.3 0  0.3 -0.3 0  0.3 0.3 0  -0.3 0.3 0] \"integer indices\" [0 1 "
      "2 0 2 3]\n"
      "AttributeEnd\n";
  auto json_equivalent = [&](const SceneDesc& from) {
    SceneDesc j = base_scene(48, 32, 16);
    j.sampler.type = "random", j.sampler.seed = 0;
    j.camera = from.camera;  // checked separately below
    Material e = emitter(1, true);
    ShapeDesc q;
    q.mesh.positions = {{-0.3f, -0.3f, 0}, {0.3f, -0.3f, 0}, {0.3f, 0.3f, 0}, {-0.3f, 0.3f, 0}};
    q.mesh.indices = {0, 1, 2, 0, 2, 3};
    q.material = add_material(j, e);
    MotionKey k0, k1;
    k1.time = 1, k1.translate = {1, 0, 0};
    q.motion = {k0, k1};
    j.shapes.push_back(q);
    return j;
  };
  // The object moves.
  SceneDesc p = import(head + light).scene;
  SceneDesc j = json_equivalent(p);
  Image a = render_quietly(p).image, b = render_quietly(j).image;
  double diff = 0, mean = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) diff += std::abs(mean_rgb(a, x, y) - mean_rgb(b, x, y)), mean += mean_rgb(b, x, y);
  EXPECT_GT(mean, 0);
  EXPECT_EQ(diff, 0);
  // The camera moves 0.5 along pbrt's camera +x (world +x here) by the end of the shutter.
  SceneDesc pc = import("ActiveTransform EndTime\nTranslate -0.5 0 0\nActiveTransform All\n" + head +
                        "AttributeBegin\n  AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" true\n"
                        "  Shape \"trianglemesh\" \"point3 P\" [-0.3 -0.3 0  0.3 -0.3 0  0.3 0.3 0  -0.3 0.3 0] "
                        "\"integer indices\" [0 1 2 0 2 3]\n"
                        "AttributeEnd\n")
                     .scene;
  ASSERT_EQ(pc.camera.motion.size(), 2u);
  expect_near(pc.camera.motion[1].position, {0.5f, 0, -5}, 1e-6f, "camera at the end");
  expect_near(pc.camera.motion[1].look_at - pc.camera.motion[1].position, {0, 0, 1}, 1e-6f,
              "view direction at the end");
  SceneDesc jc = json_equivalent(pc);
  jc.shapes[0].motion.clear();
  jc.camera.motion = {{0, {0, 0, -5}, {0, 0, -4}}, {1, {0.5f, 0, -5}, {0.5f, 0, -4}}};
  Image c = render_quietly(pc).image, e = render_quietly(jc).image;
  diff = 0, mean = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) diff += std::abs(mean_rgb(c, x, y) - mean_rgb(e, x, y)), mean += mean_rgb(e, x, y);
  EXPECT_GT(mean, 0);
  EXPECT_LT(diff, 1e-3 * mean);
}

TEST(PbrtImport, ThinDielectricAndMixMaterialsMapOntoPdrts) {
  PbrtImport im = import(
      std::string(kCamera) +
      "WorldBegin\n"
      "MakeNamedMaterial \"a\" \"string type\" \"diffuse\" \"rgb reflectance\" [0.2 0.2 0.2]\n"
      "MakeNamedMaterial \"b\" \"string type\" \"thindielectric\" \"float eta\" 1.33\n"
      "Material \"mix\" \"string materials\" [\"a\" \"b\"] \"float amount\" 0.3\n"
      "Shape \"sphere\"\n"
      "Texture \"amt\" \"float\" \"constant\" \"float value\" 0.25\n"
      "MakeNamedMaterial \"c\" \"string type\" \"mix\" \"string materials\" [\"b\" \"a\"] \"texture amount\" \"amt\"\n"
      "Material \"mix\" \"string materials\" [\"c\" \"a\"] \"float amount\" 7\n"
      "Shape \"sphere\"\n");
  EXPECT_TRUE(im.report.empty()) << im.report[0];
  const auto& ms = im.scene.materials;
  EXPECT_EQ(ms[1].type, MaterialType::ThinDielectric);
  EXPECT_FLOAT_EQ(ms[1].ior, 1.33f);
  const Material& m0 = ms[im.scene.shapes[0].material];
  EXPECT_EQ(m0.type, MaterialType::Mix);
  EXPECT_EQ(m0.mix[0], 0);
  EXPECT_EQ(m0.mix[1], 1);
  EXPECT_FLOAT_EQ(m0.amount, 0.3f);
  const Material& m1 = ms[im.scene.shapes[1].material];
  EXPECT_FLOAT_EQ(m1.amount, 1.0f);  // pbrt-v4 chooses the second outright for amount >= 1
  const Material& c = ms[size_t(m1.mix[0])];
  EXPECT_EQ(c.type, MaterialType::Mix);  // a mix of a mix
  ASSERT_EQ(c.textures.size(), 1u);
  EXPECT_EQ(c.textures[0], (TextureBinding{MaterialParam::Amount, 0}));
  const std::string w = std::string(kCamera) + "WorldBegin\nMakeNamedMaterial \"a\" \"string type\" \"diffuse\"\n";
  EXPECT_EQ(import_error(w + "Material \"mix\" \"string materials\" [\"a\" \"nope\"]\nShape \"sphere\"\n"),
            "s.pbrt:5:16: unknown named material \"nope\" in \"materials\"");
  EXPECT_EQ(import_error(w + "Material \"mix\" \"string materials\" [\"a\"]\nShape \"sphere\"\n"),
            "s.pbrt:5:16: a \"mix\" material needs \"string materials\" with two named materials");
  EXPECT_EQ(import_error(w + "Material \"mix\"\nShape \"sphere\"\n"),
            "s.pbrt:5:1: a \"mix\" material needs \"string materials\" with two named materials");
}

TEST(PbrtImport, RoughnessAndReflectanceTexturesBindThroughTheRemap) {
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\n"
                         "Texture \"r\" \"float\" \"constant\" \"float value\" 0.0625\n"
                         "Texture \"f0\" \"spectrum\" \"constant\" \"rgb value\" [0.9 0.5 0.1]\n"
                         "Material \"conductor\" \"texture roughness\" \"r\" \"texture reflectance\" \"f0\"\n"
                         "Shape \"sphere\"\n"
                         "Material \"dielectric\" \"texture roughness\" \"r\" \"bool remaproughness\" false\n"
                         "Shape \"sphere\"\n"
                         "Material \"coateddiffuse\" \"texture uroughness\" \"r\" \"float vroughness\" 0.25\n"
                         "Shape \"sphere\"\n");
  const auto& tx = im.scene.textures;
  auto mat = [&](int i) { return im.scene.materials[im.scene.shapes[i].material]; };
  // Conductor: roughness through power 1/4 (alpha = sqrt(r), pdrt roughness = sqrt(alpha)).
  const Material c = mat(0);
  ASSERT_EQ(c.textures.size(), 2u);
  EXPECT_EQ(c.textures[0].param, MaterialParam::Roughness);
  const TextureDesc& p = tx[size_t(c.textures[0].texture)];
  EXPECT_EQ(p.kind, TextureDesc::Kind::Power);
  EXPECT_EQ(p.exponent, 0.25f);
  EXPECT_EQ(p.tex.texture, 0);
  EXPECT_EQ(c.textures[1], (TextureBinding{MaterialParam::Reflectance, 1}));
  // Dielectric without remapping: roughness is alpha, pdrt roughness sqrt(alpha).
  const TextureDesc& q = tx[size_t(mat(1).textures.at(0).texture)];
  EXPECT_EQ(q.kind, TextureDesc::Kind::Power);
  EXPECT_EQ(q.exponent, 0.5f);
  // Anisotropic: the mean of uroughness and vroughness (a mix by 1/2), then the remap; reported.
  const TextureDesc& a = tx[size_t(mat(2).textures.at(0).texture)];
  ASSERT_EQ(a.kind, TextureDesc::Kind::Power);
  const TextureDesc& mean = tx[size_t(a.tex.texture)];
  EXPECT_EQ(mean.kind, TextureDesc::Kind::Mix);
  EXPECT_EQ(mean.tex1.texture, 0);
  EXPECT_EQ(mean.tex2.value.x, 0.25f);
  EXPECT_EQ(mean.amount.value.x, 0.5f);
  const std::vector<std::string> report = report_besides_rgb(im.report);
  ASSERT_EQ(report.size(), 1u);
  EXPECT_NE(report[0].find("s.pbrt:10:1: anisotropic roughness"), std::string::npos) << report[0];
}

TEST(PbrtImport, ScaleAndMixTexturesAndImagemapScaleAndInvert) {
  const std::filesystem::path dir = ply_dir();
  write_file(dir / "wood.png", "not read while loading");
  write_file(
      dir / "s.pbrt",
      std::string(kCamera) +
          "WorldBegin\n"
          "Texture \"c\" \"spectrum\" \"constant\" \"rgb value\" [0.1 0.2 0.3]\n"
          "Texture \"f\" \"float\" \"constant\" \"float value\" 0.4\n"
          "Texture \"s\" \"spectrum\" \"scale\" \"texture tex\" \"c\" \"float scale\" 2\n"
          "Texture \"m\" \"spectrum\" \"mix\" \"texture tex1\" \"s\" \"rgb tex2\" [1 1 1] \"texture amount\" \"f\"\n"
          "Texture \"img\" \"spectrum\" \"imagemap\" \"string filename\" \"wood.png\" \"float scale\" 0.5 \"bool "
          "invert\" true\n"
          "Texture \"inv\" \"float\" \"imagemap\" \"string filename\" \"wood.png\" \"bool invert\" true\n"
          "Material \"diffuse\" \"texture reflectance\" \"m\"\n"
          "Shape \"sphere\"\n"
          "Material \"diffuse\" \"texture reflectance\" \"img\"\n"
          "Shape \"sphere\"\n");
  PbrtImport im = load_pbrt_scene(dir / "s.pbrt", false);
  EXPECT_TRUE(report_besides_rgb(im.report).empty());
  const auto& tx = im.scene.textures;
  ASSERT_EQ(tx.size(), 9u);  // c, f, s, m, img's image, scale and invert, inv's image and invert
  EXPECT_EQ(tx[2].kind, TextureDesc::Kind::Scale);
  EXPECT_EQ(tx[2].tex.texture, 0);
  EXPECT_EQ(tx[2].scale.value.x, 2.0f);
  EXPECT_EQ(tx[3].kind, TextureDesc::Kind::Mix);
  EXPECT_EQ(tx[3].tex1.texture, 2);
  EXPECT_EQ(tx[3].tex2.value.y, 1.0f);
  EXPECT_EQ(tx[3].amount.texture, 1);
  EXPECT_EQ(tx[4].kind, TextureDesc::Kind::Image);
  EXPECT_EQ(tx[5].kind, TextureDesc::Kind::Scale);  // pbrt-v4: invert(scale x)
  EXPECT_EQ(tx[5].tex.texture, 4);
  EXPECT_EQ(tx[5].scale.value.x, 0.5f);
  EXPECT_EQ(tx[6].kind, TextureDesc::Kind::Invert);
  EXPECT_EQ(tx[6].tex.texture, 5);
  EXPECT_EQ(tx[6].name, "img");
  EXPECT_EQ(tx[8].kind, TextureDesc::Kind::Invert);  // invert alone: no scale node
  EXPECT_EQ(tx[8].tex.texture, 7);
  EXPECT_EQ(im.scene.materials[im.scene.shapes[0].material].textures[0].texture, 3);
  EXPECT_EQ(im.scene.materials[im.scene.shapes[1].material].textures[0].texture, 6);
  write_file(
      dir / "t.pbrt",
      std::string(kCamera) + "WorldBegin\nTexture \"s\" \"float\" \"scale\" \"float scale\" -1\nShape \"sphere\"\n");
  EXPECT_EQ(file_import_error(dir / "t.pbrt"), (dir / "t.pbrt").string() + ":4:29: \"scale\" must be >= 0, got -1");
  std::filesystem::remove_all(dir);
}

// The new materials and the roughness remap render what their JSON equivalents render: a
// sphere of a mix of diffuse and thin dielectric, a floor of a conductor with a texture
// roughness (pbrt 0.04, remapped: pdrt roughness 0.04^(1/4)) and a texture reflectance.
TEST(PbrtImport, MixThinDielectricAndRoughnessTexturesRenderTheirJsonEquivalent) {
  PbrtImport im =
      import(kTwinHeader +
             "MakeNamedMaterial \"d\" \"string type\" \"diffuse\" \"rgb reflectance\" [0.6 0.5 0.4]\n"
             "MakeNamedMaterial \"t\" \"string type\" \"thindielectric\" \"float eta\" 1.5\n"
             "Texture \"r\" \"float\" \"constant\" \"float value\" 0.04\n"
             "Texture \"f0\" \"spectrum\" \"constant\" \"rgb value\" [0.9 0.6 0.3]\n" +
             kTwinLamp +
             "Material \"conductor\" \"texture roughness\" \"r\" \"texture reflectance\" \"f0\"\n"
             "Shape \"trianglemesh\" \"point3 P\" [-3 0 -3  3 0 -3  3 0 3  -3 0 3] \"integer indices\" [0 2 1 0 3 2]\n"
             "Material \"mix\" \"string materials\" [\"d\" \"t\"] \"float amount\" 0.3\n"
             "Translate 0 0.5 0\n"
             "Shape \"sphere\" \"float radius\" 0.5\n");
  SceneDesc j = twin_scene();
  // Materials in the importer's order (a mix's choice hashes its index): d, t, light, floor, mix.
  Material d = diffuse(0);
  d.albedo = {0.6f, 0.5f, 0.4f};
  const int di = add_material(j, d);
  Material t;
  t.type = MaterialType::ThinDielectric;
  t.albedo = Vec3(1.0f);
  t.ior = 1.5f;
  const int ti = add_material(j, t);
  add_twin_lamp(j);
  Material floor;
  floor.type = MaterialType::Conductor;
  floor.roughness = std::pow(0.04f, 0.25f);
  floor.energy_compensation = false;  // pbrt-v4 has none
  conductor_from_reflectance({0.9f, 0.6f, 0.3f}, &floor);
  ShapeDesc fq;
  fq.mesh.positions = {{-3, 0, -3}, {3, 0, -3}, {3, 0, 3}, {-3, 0, 3}};
  fq.mesh.indices = {0, 2, 1, 0, 3, 2};
  fq.material = add_material(j, floor);
  j.shapes.push_back(fq);
  Material mix;
  mix.type = MaterialType::Mix;
  mix.mix[0] = di, mix.mix[1] = ti, mix.amount = 0.3f;
  j.shapes.push_back(sphere({0, 0.5f, 0}, 0.5f, add_material(j, mix)));

  SceneDesc& p = im.scene;
  ASSERT_EQ(p.materials.size(), j.materials.size());
  expect_renders_agree(p, j);
}

// --- orthographic camera, screen window, frame aspect ratio, crop window ---------------------

namespace {

const char* kLookAt = "LookAt 0 0 -5  0 0 0  0 1 0\n";

std::string film(int w, int h, const std::string& extra = "") {
  return "Film \"rgb\" \"integer xresolution\" " + std::to_string(w) + " \"integer yresolution\" " + std::to_string(h) +
         (extra.empty() ? "" : " " + extra) + "\n";
}

void expect_window(const CameraDesc& c, std::array<float, 4> w, const std::string& what) {
  ASSERT_TRUE(c.has_screen_window) << what;
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(c.screen_window[i], w[i], 1e-6f) << what << " bound " << i;
}

}  // namespace

// pbrt-v4's orthographic camera: its default screen window spans [-1, 1] on the shorter side,
// which is pdrt's ortho_height 2 on a landscape film and 2 height / width on a portrait one;
// lensradius and focaldistance are the thin lens's.
TEST(PbrtImport, OrthographicCameraMapsOntoPdrts) {
  const std::string cam =
      std::string(kLookAt) + "Camera \"orthographic\" \"float lensradius\" 0.1 \"float focaldistance\" 4\n";
  PbrtImport im = import(cam + film(200, 100) + "WorldBegin\nShape \"sphere\"\n");
  const CameraDesc& c = im.scene.camera;
  EXPECT_EQ(c.projection, CameraDesc::Projection::Orthographic);
  EXPECT_FALSE(c.has_screen_window);
  EXPECT_FLOAT_EQ(c.ortho_height, 2);
  EXPECT_FLOAT_EQ(c.aperture_radius, 0.1f);
  EXPECT_FLOAT_EQ(c.focus_distance, 4);
  EXPECT_TRUE(c.flip_x);
  // pbrt-v4 starts every lens ray at the lens offset from the camera's centre (mmp/pbrt-v3#315);
  // pdrt moves each film point's own origin, and says so.
  ASSERT_EQ(im.report.size(), 1u);
  EXPECT_NE(im.report[0].find("s.pbrt:2:23: orthographic depth of field moves each ray's own origin"),
            std::string::npos)
      << im.report[0];
  PbrtImport p = import(cam + film(100, 200) + "WorldBegin\nShape \"sphere\"\n");
  EXPECT_FLOAT_EQ(p.scene.camera.ortho_height, 4);
  // A uniformly scaled camera space scales the window: Scale 3 before LookAt makes camera
  // units a third of a world unit.
  PbrtImport s = import("Scale 3 3 3\n" + cam + film(200, 100) + "WorldBegin\nShape \"sphere\"\n");
  EXPECT_NEAR(s.scene.camera.ortho_height, 2.0f / 3, 1e-6f);
}

// "screenwindow" replaces the default; "frameaspectratio" replaces the film's aspect in it. The
// perspective camera's window is pbrt's times tan(fov / 2) (pbrt's screen space is scaled by
// 1 / tan(fov / 2)); the orthographic camera's is pbrt's.
TEST(PbrtImport, ScreenWindowAndFrameAspectRatioMapOntoPdrtsWindow) {
  const float t = std::tan(15 * kPi / 180);
  const std::string persp = std::string(kLookAt) + "Camera \"perspective\" \"float fov\" 30 ";
  const std::string ortho = std::string(kLookAt) + "Camera \"orthographic\" ";
  const std::string world = "WorldBegin\nShape \"sphere\"\n";
  expect_window(import(persp + "\"float screenwindow\" [-0.5 1 -1 0.25]\n" + film(64, 64) + world).scene.camera,
                {-0.5f * t, t, -t, 0.25f * t}, "perspective screenwindow");
  expect_window(import(persp + "\"float frameaspectratio\" 2\n" + film(64, 64) + world).scene.camera,
                {-2 * t, 2 * t, -t, t}, "perspective frameaspectratio 2");
  expect_window(import(persp + "\"float frameaspectratio\" 0.5\n" + film(64, 64) + world).scene.camera,
                {-t, t, -2 * t, 2 * t}, "perspective frameaspectratio 0.5");
  expect_window(import(ortho + "\"float screenwindow\" [0 2 -0.5 0.5]\n" + film(64, 32) + world).scene.camera,
                {0, 2, -0.5f, 0.5f}, "orthographic screenwindow");
  expect_window(import(ortho + "\"float frameaspectratio\" 0.25\n" + film(64, 32) + world).scene.camera, {-1, 1, -4, 4},
                "orthographic frameaspectratio");
  // Without either the window stays implicit: the fov conversion (vfov) covers it.
  EXPECT_FALSE(import(persp + "\n" + film(64, 32) + world).scene.camera.has_screen_window);
  EXPECT_EQ(import_error(persp + "\"float screenwindow\" [-1 1 -1]\n" + world),
            "s.pbrt:2:37: \"float screenwindow\" needs 4 values [x0 x1 y0 y1], got 3");
  EXPECT_EQ(import_error(persp + "\"float screenwindow\" [1 -1 -1 1]\n" + world),
            "s.pbrt:2:37: \"float screenwindow\" must have x0 < x1 and y0 < y1");
  EXPECT_EQ(import_error(persp + "\"float frameaspectratio\" 0\n" + world),
            "s.pbrt:2:37: \"float frameaspectratio\" must be > 0, got 0");
}

// pbrt-v4's cropwindow (each pair sorted, clamped to [0, 1]) and pixelbounds (pixels, each
// pair sorted; the crop window wins when both are given).
TEST(PbrtImport, CropWindowAndPixelBoundsMapOntoPdrtsCropWindow) {
  const std::string head = std::string(kCamera);
  const std::string world = "WorldBegin\nShape \"sphere\"\n";
  EXPECT_EQ(import(head + film(200, 100, "\"float cropwindow\" [0.9 0.2 0 0.5]") + world).scene.film.crop_window,
            (std::array<float, 4>{0.2f, 0.9f, 0, 0.5f}));
  EXPECT_EQ(import(head + film(200, 100, "\"float cropwindow\" [-0.5 0.5 0.25 2]") + world).scene.film.crop_window,
            (std::array<float, 4>{0, 0.5f, 0.25f, 1}));
  PbrtImport pb = import(head + film(200, 100, "\"integer pixelbounds\" [10 20 5 15]") + world);
  PixelRect r = crop_pixels(pb.scene.film.crop_window, 200, 100);
  EXPECT_EQ(r.x0, 10);
  EXPECT_EQ(r.x1, 20);
  EXPECT_EQ(r.y0, 5);
  EXPECT_EQ(r.y1, 15);
  r = crop_pixels(import(head + film(200, 100, "\"integer pixelbounds\" [20 10 15 5]") + world).scene.film.crop_window,
                  200, 100);
  EXPECT_EQ(r.x0, 10);
  EXPECT_EQ(r.y1, 15);
  PbrtImport both =
      import(head + film(200, 100, "\"integer pixelbounds\" [10 20 5 15] \"float cropwindow\" [0 0.5 0 1]") + world);
  EXPECT_EQ(both.scene.film.crop_window, (std::array<float, 4>{0, 0.5f, 0, 1}));
  ASSERT_EQ(both.report.size(), 1u);
  EXPECT_EQ(both.report[0], "s.pbrt:3:64: both \"cropwindow\" and \"pixelbounds\" (the crop window used, as pbrt-v4)");
  EXPECT_EQ(import_error(head + film(200, 100, "\"float cropwindow\" [0 1 0]") + world),
            "s.pbrt:3:64: \"float cropwindow\" needs 4 values [x0 x1 y0 y1], got 3");
  EXPECT_EQ(import_error(head + film(200, 100, "\"float cropwindow\" [0.5 0.5 0 1]") + world),
            "s.pbrt:3:64: \"float cropwindow\" covers no pixel of the 200x100 film (pixels ceil(size * bound) are "
            "[100, 100) x [0, 100))");
  EXPECT_EQ(import_error(head + film(200, 100, "\"integer pixelbounds\" [300 400 0 10]") + world),
            "s.pbrt:3:64: \"integer pixelbounds\" covers no pixel of the 200x100 film (pixels ceil(size * bound) are "
            "[200, 200) x [0, 10))");
}

// pbrt's camera space is left-handed: LookAt from -z towards the origin puts world +x on the
// image's right (flip_x). With screenwindow [0 2 -0.5 0.5] the 64 x 32 film covers camera x
// in [0, 2], so an emitter at world (1.5, 0.25) images at pixel (48, 8): right of centre and
// in the upper half, as in pbrt.
TEST(PbrtImport, OrthographicOffCentreWindowPutsAnOffAxisObjectOnPbrtsSide) {
  PbrtImport im =
      import(std::string(kLookAt) + "Camera \"orthographic\" \"float screenwindow\" [0 2 -0.5 0.5]\n" + film(64, 32) +
             "Sampler \"independent\" \"integer pixelsamples\" 16\nPixelFilter \"box\"\n"
             "WorldBegin\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
             "Translate 1.5 0.25 0\nShape \"sphere\" \"float radius\" 0.1\nAttributeEnd\n");
  auto p = ThinLensCamera(im.scene.camera, 64, 32).project({1.5f, 0.25f, 0});
  EXPECT_NEAR(p[0], 48, 1e-4);
  EXPECT_NEAR(p[1], 8, 1e-4);
  Image img = render_quietly(im.scene).image;
  double w = 0, sx = 0, sy = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) {
      const double v = mean_rgb(img, x, y);
      w += v, sx += v * (x + 0.5), sy += v * (y + 0.5);
    }
  ASSERT_GT(w, 0);
  EXPECT_NEAR(sx / w, 48, 0.1);  // 3.2 px radius disk; tolerance for rim sampling noise at 16 spp
  EXPECT_NEAR(sy / w, 8, 0.1);
}

// An orthographic pbrt scene with an off-centre screen window, depth of field and a crop
// window renders the image of the SceneDesc its JSON would give.
TEST(PbrtImport, OrthographicCroppedSceneRendersTheImageOfItsJsonEquivalent) {
  PbrtImport im = import(
      "LookAt 0 1 -6  0 0.5 0  0 1 0\n"
      "Camera \"orthographic\" \"float screenwindow\" [-1.2 1.8 -1 1] \"float lensradius\" 0.05 \"float "
      "focaldistance\" 6\n"
      "Film \"rgb\" \"integer xresolution\" 48 \"integer yresolution\" 32 \"float cropwindow\" [0.3 0.8 0.2 0.9]\n"
      "Sampler \"independent\" \"integer pixelsamples\" 8\n"
      "Integrator \"path\" \"integer maxdepth\" 4\n"
      "PixelFilter \"box\"\n"
      "WorldBegin\n" +
      kTwinLamp +
      "Material \"diffuse\" \"rgb reflectance\" [0.6 0.5 0.4]\n"
      "Translate 0.4 0.5 0\n"
      "Shape \"sphere\" \"float radius\" 0.5\n");
  SceneDesc j = base_scene(48, 32, 8);
  j.camera.projection = CameraDesc::Projection::Orthographic;
  j.camera.has_screen_window = true;
  j.camera.screen_window = {-1.2f, 1.8f, -1, 1};
  j.camera.aperture_radius = 0.05f, j.camera.focus_distance = 6;
  j.camera.position = {0, 1, -6};
  j.camera.look_at = {0, 0.5, 0};
  j.camera.flip_x = true;
  j.film.crop_window = {0.3f, 0.8f, 0.2f, 0.9f};
  j.sampler.type = "random";
  j.sampler.seed = 0;
  j.integrator.max_depth = 4;
  add_twin_lamp(j);
  Material red = diffuse(0);
  red.albedo = {0.6f, 0.5f, 0.4f};
  j.shapes.push_back(sphere({0.4f, 0.5f, 0}, 0.5f, add_material(j, red)));

  SceneDesc& p = im.scene;
  j.camera.up = p.camera.up;  // orthogonalised to the view by the importer (see above)
  p.camera.look_at = p.camera.position +
                     normalize(p.camera.look_at - p.camera.position) * length(j.camera.look_at - j.camera.position);
  Image a = render_quietly(p).image, b = render_quietly(j).image;
  ASSERT_EQ(a.width, 24);   // ceil(48 0.3) = 15 .. ceil(48 0.8) = 39
  ASSERT_EQ(a.height, 22);  // ceil(32 0.2) = 7 .. ceil(32 0.9) = 29
  ASSERT_EQ(b.width, a.width);
  ASSERT_EQ(b.height, a.height);
  double worst = 0, sum = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      worst = std::max(worst, std::abs(mean_rgb(a, x, y) - mean_rgb(b, x, y)));
      sum += mean_rgb(b, x, y);
    }
  EXPECT_GT(sum, 0);
  EXPECT_LT(worst, 1e-4 * std::max(1.0, sum / (a.width * a.height)));
}

// Found with tests/fuzz/fuzz_pbrt.cpp: a stratified sampler's two counts are checked one by one,
// before their product, which overflowed (undefined behaviour) for two large ones.
TEST(PbrtImport, StratifiedSampleCountsTooLargeToMultiplyAreRefused) {
  EXPECT_EQ(import_error("Sampler \"stratified\" \"integer xsamples\" [9000000000000000] \"integer ysamples\" "
                         "[9000000000000000]\n" +
                         std::string(kCamera) + "WorldBegin\nShape \"sphere\"\n"),
            "s.pbrt:1:1: \"integer xsamples\" and \"integer ysamples\" must be in [1, 2^24], got 9000000000000000 and "
            "9000000000000000");
}

namespace {

// Position and uv of the bilinear patch with corners p00 p10 p01 p11 at (u, v).
template <class T>
T bilerp(const T c[4], double u, double v) {
  return c[0] * float((1 - u) * (1 - v)) + c[1] * float(u * (1 - v)) + c[2] * float((1 - u) * v) + c[3] * float(u * v);
}

// Largest distance between points linearly interpolated on the imported triangles and the
// patch at the same uv (uv is the patch's own (u, v) here), and the triangle count.
double worst_patch_error(const MeshData& m, const Vec3 corners[4], int* triangles) {
  double worst = 0;
  *triangles = int(m.indices.size() / 3);
  if (m.uvs.size() != m.positions.size()) return INFINITY;  // the patch's uv must be there
  for (size_t t = 0; t < m.indices.size(); t += 3)
    for (auto [b1, b2] :
         std::vector<std::pair<float, float>>{{1.f / 3, 1.f / 3}, {0.5f, 0.5f}, {0.5f, 0}, {0.1f, 0.7f}}) {
      const float b0 = 1 - b1 - b2;
      const uint32_t i0 = m.indices[t], i1 = m.indices[t + 1], i2 = m.indices[t + 2];
      const Vec3 q = m.positions[i0] * b0 + m.positions[i1] * b1 + m.positions[i2] * b2;
      const double u = b0 * m.uvs[i0][0] + b1 * m.uvs[i1][0] + b2 * m.uvs[i2][0];
      const double v = b0 * m.uvs[i0][1] + b1 * m.uvs[i1][1] + b2 * m.uvs[i2][1];
      worst = std::max(worst, double(length(q - bilerp(corners, u, v))));
    }
  return worst;
}

}  // namespace

TEST(PbrtImport, TwistedBilinearPatchIsTessellatedWithinItsToleranceWithBilinearUv) {
  // A saddle: two triangles would miss its centre by 0.25; pbrt-v4 intersects the patch.
  const Vec3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}};
  PbrtImport im =
      import(std::string(kCamera) + "WorldBegin\nShape \"bilinearmesh\" \"point3 P\" [0 0 0  1 0 0  0 1 0  1 1 1]\n");
  ASSERT_EQ(im.scene.shapes.size(), 1u);
  int triangles = 0;
  EXPECT_LT(worst_patch_error(im.scene.shapes[0].mesh, corners, &triangles), 1e-4 * std::sqrt(2.0));
  EXPECT_GT(triangles, 2);
  EXPECT_LE(triangles, 2 * 64 * 64);
  EXPECT_TRUE(im.report.empty());
}

TEST(PbrtImport, PlanarPatchWithNonAffineUvGetsBilinearUvNotADiagonalSeam) {
  // The unit square with uv corners (0,0) (1,0) (0,1) (2,2): uv is bilinear in position.
  PbrtImport im = import(std::string(kCamera) +
                         "WorldBegin\nShape \"bilinearmesh\" \"point3 P\" [0 0 0  1 0 0  0 1 0  1 1 0] "
                         "\"point2 uv\" [0 0  1 0  0 1  2 2]\n");
  ASSERT_EQ(im.scene.shapes.size(), 1u);
  const MeshData& m = im.scene.shapes[0].mesh;
  const std::array<float, 2> uv[4] = {{0, 0}, {1, 0}, {0, 1}, {2, 2}};
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  double worst = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3)
    for (auto [b1, b2] : std::vector<std::pair<float, float>>{{1.f / 3, 1.f / 3}, {0.5f, 0.5f}, {0.1f, 0.7f}}) {
      const float b0 = 1 - b1 - b2;
      const uint32_t i[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
      const Vec3 q = m.positions[i[0]] * b0 + m.positions[i[1]] * b1 + m.positions[i[2]] * b2;
      for (int k = 0; k < 2; ++k) {
        const double got = b0 * m.uvs[i[0]][k] + b1 * m.uvs[i[1]][k] + b2 * m.uvs[i[2]][k];
        const double want = (1 - q.x) * (1 - q.y) * uv[0][k] + q.x * (1 - q.y) * uv[1][k] + (1 - q.x) * q.y * uv[2][k] +
                            q.x * q.y * uv[3][k];
        worst = std::max(worst, std::abs(got - want));
      }
    }
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(m.indices.size(), 6u);
}
