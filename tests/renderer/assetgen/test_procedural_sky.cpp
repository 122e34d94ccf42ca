// The generated sky (renderer/assetgen/): deterministic pixels and files, a plausible HDR sky.
#include "renderer/assetgen/procedural_sky.h"
#include "renderer/render/environment_map.h"
#include "renderer/scene/equirect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace pdrt;

namespace {

std::string read_bytes(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(ProceduralSky, SamePixelsEveryTime) {
  const std::vector<float> a = procedural_sky(), b = procedural_sky();
  ASSERT_EQ(a.size(), 512u * 256u * 3u);
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float)));
}

// The generator run twice writes the same bytes, and the same as the build's sky.exr.
TEST(ProceduralSky, GeneratorWritesTheSameFileTwice) {
  const fs::path dir = fs::temp_directory_path() / ("pdrt_sky_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const char* name : {"a.exr", "b.exr"}) {
    const std::string cmd = std::string("'") + PDRT_SKY_GEN + "' '" + (dir / name).string() + "'";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  }
  const std::string a = read_bytes(dir / "a.exr"), b = read_bytes(dir / "b.exr");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, b);
  EXPECT_EQ(a, read_bytes(fs::path(PDRT_ASSET_DIR) / "sky.exr"));
  fs::remove_all(dir);
}

// Finite and >= 0 everywhere; the sun is thousands of times the sky; blue above, ground below;
// and the sun carries a good share of the map's light (so it casts shadows).
TEST(ProceduralSky, HasASunASkyAndAGround) {
  const SkyParams p;
  const std::vector<float> rgb = procedural_sky(p);
  for (float v : rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0) << v;
  const EnvironmentMap map(p.width, p.height, rgb, Vec3(1.0f), 0);
  const Vec3 sun = map.radiance(p.to_sun), zenith = map.radiance({0, 1, 0}), ground = map.radiance({0.3f, -0.9f, 0.1f});
  EXPECT_GT(luminance(sun), 500.0f);
  EXPECT_LT(luminance(zenith), 1.0f);
  EXPECT_GT(zenith.z, zenith.x);
  EXPECT_LT(luminance(ground), luminance(zenith));
  // Irradiance from the sun disc alone on a surface facing it vs. the whole map's estimate.
  const double r = p.sun_radius_deg * M_PI / 180, disc = 2 * M_PI * (1 - std::cos(r));
  EXPECT_GT(luminance(p.sun_radiance) * 0.8 * disc, 0.3 * map.irradiance_estimate());
}
