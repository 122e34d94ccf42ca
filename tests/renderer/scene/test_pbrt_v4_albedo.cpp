// pbrt files rendered against pbrt-v4's own numbers (docs/pbrt-import.md, "Checked against
// pbrt-v4"): a large plane of one material, seen by an orthographic camera at cos(theta) from
// its normal, at maxdepth 1, under an infinite light.
// - A uniform white light: every pixel shows the material's directional albedo. The expected
//   values are the albedos pbrt-v4's BxDF code gives (the mean path weight of its Sample_f over
//   4M draws, standard errors below 0.0002), what a pbrt-v4 render of these files converges
//   to: its path integrator reaches a uniform infinite light by BSDF sampling alone.
// - An equal-area octahedral image: the expected values are pbrt-v4's path-integrator
//   estimator at that vertex (its ImageInfiniteLight with the compensated distribution, its
//   BxDFs' f, Sample_f and PDF, the power heuristic) averaged over 4e7 draws, standard errors
//   about 0.01 %.
#include "renderer/image/image_output.h"
#include "renderer/scene/pbrt/equal_area_octahedral.h"
#include "renderer/scene/pbrt/pbrt_parser.h"
#include "renderer/scene/pbrt/pbrt_scene_builder.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

using namespace pdrt;
using namespace pdrt::test;

namespace {

// The mean of the 32 x 32 image of `material` seen at cos(theta) = c under `light`, at 1024 spp
// (standard error about 0.12 % of the mean for the materials below); `dir` holds the light's
// image, if any.
double plane_mean(const std::string& material, double c, const std::string& light = "\"rgb L\" [1 1 1]",
                  const std::filesystem::path& dir = ".") {
  const double s = std::sqrt(1 - c * c);
  const std::string up = c == 1 ? "0 1 0" : "0 0 1";
  const std::string text =
      "Integrator \"path\" \"integer maxdepth\" [ 1 ]\n"
      "Sampler \"independent\" \"integer pixelsamples\" [ 1024 ]\n"
      "PixelFilter \"box\"\n"
      "Film \"rgb\" \"integer xresolution\" [ 32 ] \"integer yresolution\" [ 32 ]\n"
      "LookAt " +
      std::to_string(10 * s) + " 0 " + std::to_string(10 * c) + "  0 0 0  " + up + "\n" +
      "Camera \"orthographic\" \"float screenwindow\" [-0.1 0.1 -0.1 0.1]\n"
      "WorldBegin\n"
      "LightSource \"infinite\" " +
      light + "\n" + "Material " + material + "\n" +
      "Shape \"trianglemesh\" \"point3 P\" [-1000 -1000 0  1000 -1000 0  1000 1000 0  -1000 1000 0] "
      "\"integer indices\" [0 1 2 0 2 3]\n";
  PbrtImport im = build_pbrt_scene(parse_pbrt_text(text, (dir / "plane.pbrt").string(), dir), false);
  // Nothing to report but an image's resampling (its texels seen directly; none are here).
  for (const std::string& line : im.report)
    EXPECT_NE(line.find("is resampled to pdrt's equirectangular map"), std::string::npos) << line;
  const Image img = render_quietly(im.scene).image;
  double sum = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) sum += mean_rgb(img, x, y);
  return sum / (32 * 32);
}

double furnace_albedo(const std::string& material, double c) { return plane_mean(material, c); }

// The sky of the image-light cases, as a 256 x 256 equal-area octahedral image written to a
// scratch directory: grey L(w) = 0.3 + 3 max(0, w . s)^8 at each texel's centre direction, s =
// normalize(0.5, 0.3, 0.8), a soft sun over a sky dimmer than the average.
std::filesystem::path sky_image_dir() {
  const auto dir = std::filesystem::temp_directory_path() / ("pdrt_pbrt_v4_sky_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const int n = 256;
  const Vec3 sun = normalize(Vec3(0.5f, 0.3f, 0.8f));
  std::vector<float> rgb;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Vec3 w = equal_area_square_to_sphere((x + 0.5) / n, (y + 0.5) / n);
      const float v = float(0.3 + 3 * std::pow(std::max(0.0, double(dot(w, sun))), 8));
      rgb.insert(rgb.end(), {v, v, v});
    }
  write_linear_rgb(dir / "sky.exr", n, n, rgb, {});
  return dir;
}

double under_the_sky(const std::string& material, double c) {
  const auto dir = sky_image_dir();
  const double m = plane_mean(material, c, "\"string filename\" \"sky.exr\"", dir);
  std::filesystem::remove_all(dir);
  return m;
}

}  // namespace

// pbrt-v4's layered BxDF: f() (light sampling) averages 7 % above Sample_f() (pbrt-v4 issue
// #187), so light-sampling the environment as well put pdrt 1.1 % above pbrt-v4 here.
TEST(PbrtV4Albedo, CoatedConductorUnderAUniformInfiniteLight) {
  const double a = furnace_albedo(
      "\"coatedconductor\" \"float interface.roughness\" 0.15 \"float interface.eta\" 1.5 "
      "\"rgb conductor.eta\" [0.2 0.2 0.2] \"rgb conductor.k\" [3 3 3] \"float conductor.roughness\" 0.3",
      0.7);
  EXPECT_NEAR(a, 0.300481, 0.006 * 0.300481);  // ±0.6 %: 5 standard errors
}

TEST(PbrtV4Albedo, CoatedDiffuseUnderAUniformInfiniteLight) {
  const double a = furnace_albedo("\"coateddiffuse\" \"rgb reflectance\" [0.8 0.8 0.8] \"float roughness\" 0.15", 0.4);
  EXPECT_NEAR(a, 0.424985, 0.006 * 0.424985);
}

TEST(PbrtV4Albedo, RoughConductorUnderAUniformInfiniteLight) {
  const double a =
      furnace_albedo("\"conductor\" \"rgb eta\" [0.2 0.2 0.2] \"rgb k\" [3 3 3] \"float roughness\" 0.5", 0.7);
  EXPECT_NEAR(a, 0.496323, 0.006 * 0.496323);
}

TEST(PbrtV4Albedo, RoughDielectricUnderAUniformInfiniteLight) {
  const double a = furnace_albedo("\"dielectric\" \"float eta\" 1.5 \"float roughness\" 0.3", 0.15);
  EXPECT_NEAR(a, 0.413092, 0.006 * 0.413092);
}

// Under an image light, pbrt-v4 light-samples from the image less its average (MIS
// compensation), which raises the light samples' MIS weight where the sky is bright, and with
// it the share of the layered BxDF's f() bias. Sampled by the image itself, pdrt was 1.8 %
// (coated diffuse) and 1.2 % (coated conductor) below pbrt-v4 here. ±0.4 %: 6 standard errors
// of these renders (0.06-0.07 %; pbrt-v4's values have 0.01 %).
TEST(PbrtV4Albedo, CoatedDiffuseUnderAnImageInfiniteLight) {
  const double a = under_the_sky("\"coateddiffuse\" \"rgb reflectance\" [0.5 0.5 0.5] \"float roughness\" 0.15", 1.0);
  EXPECT_NEAR(a, 0.2139907, 0.004 * 0.2139907);
}

TEST(PbrtV4Albedo, CoatedConductorUnderAnImageInfiniteLight) {
  const double a = under_the_sky(
      "\"coatedconductor\" \"float interface.roughness\" 0.15 \"float interface.eta\" 1.5 "
      "\"rgb conductor.eta\" [0.2 0.2 0.2] \"rgb conductor.k\" [3 3 3] \"float conductor.roughness\" 0.3",
      1.0);
  EXPECT_NEAR(a, 0.2627362, 0.004 * 0.2627362);
}
