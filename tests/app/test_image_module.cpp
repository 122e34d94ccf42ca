// The image module: OpenImageIO is loaded only by commands that read or write images.
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace pdrt {
namespace {

using test::run_pdrt;
namespace fs = std::filesystem;

// Sets an environment variable for the pdrt processes a test starts.
struct ScopedEnv {
  ScopedEnv(const char* name, const char* value) : name(name) { ::setenv(name, value, 1); }
  ~ScopedEnv() { ::unsetenv(name); }
  const char* name;
};

TEST(ImageModule, PdrtDoesNotLinkOpenImageIO) {
  std::string cmd = "ldd '" + std::string(PDRT_BINARY) + "'";
  FILE* p = ::popen(cmd.c_str(), "r");
  ASSERT_TRUE(p);
  std::string out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  ASSERT_EQ(::pclose(p), 0) << out;
  EXPECT_NE(out.find("libc.so"), std::string::npos) << out;
  EXPECT_EQ(out.find("OpenImageIO"), std::string::npos) << out;
}

TEST(ImageModule, CommandsWithoutImagesNeverLoadIt) {
  fs::path d = test::scratch_dir("module_unused");
  ScopedEnv env("PDRT_IMAGE_MODULE", "/nonexistent/libpdrt_image.so");
  auto r = run_pdrt("sample -m random -n 10 -q -o " + (d / "p.csv").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(d / "p.csv"));
}

TEST(ImageModule, MissingModuleIsRefusedBeforeRenderingNamingThePath) {
  fs::path d = test::scratch_dir("module_missing");
  std::ofstream(d / "scene.json") << R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
    "film": {"width": 8, "height": 8}, "sampler": {"spp": 1},
    "objects": [], "lights": [{"type": "environment", "radiance": [1, 1, 1]}]})";
  ScopedEnv env("PDRT_IMAGE_MODULE", "/nonexistent/libpdrt_image.so");
  auto r = run_pdrt("render " + (d / "scene.json").string() + " -o " + (d / "out.exr").string() + " --stats " +
                    (d / "stats.json").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/libpdrt_image.so"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No such file"), std::string::npos) << "dlerror() should say why: " << r.err;
  EXPECT_FALSE(fs::exists(d / "out.exr"));
  EXPECT_FALSE(fs::exists(d / "stats.json"));
}

// The module loads on its own thread while the scene does (image_module_preload.h); a scene
// that fails to load is what the user hears of, not the module the render never reached.
TEST(ImageModule, ASceneErrorIsReportedWhileAMissingModuleLoadsBesideIt) {
  fs::path d = test::scratch_dir("module_missing_scene_error");
  std::ofstream(d / "scene.json") << R"({"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
    "film": {"width": 8, "height": -8}, "sampler": {"spp": 1},
    "objects": [], "lights": [{"type": "environment", "radiance": [1, 1, 1]}]})";
  ScopedEnv env("PDRT_IMAGE_MODULE", "/nonexistent/libpdrt_image.so");
  auto r = run_pdrt("render " + (d / "scene.json").string() + " -o " + (d / "out.exr").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("height"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("libpdrt_image"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "out.exr"));
}

}  // namespace
}  // namespace pdrt
