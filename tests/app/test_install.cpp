// `cmake --install` (issue 29): an installed pdrt, moved anywhere, renders with the files installed
// beside it. Each lookup is shown to read the installed copy by breaking that copy and seeing
// the error name it (the build tree's files are still there, so a fallback would hide nothing).
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace pdrt {
namespace {

namespace fs = std::filesystem;

// One install per test program, copied to another prefix (relocated) for each test.
const fs::path& installed_prefix() {
  static const fs::path prefix = [] {
    const fs::path p = test::scratch_base() / "install-a";
    const std::string cmd = std::string("'") + PDRT_CMAKE + "' --install '" + PDRT_BUILD_DIR + "' --prefix '" +
                            p.string() + "' >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return p;
  }();
  return prefix;
}

struct InstalledRun {
  int code;
  std::string err;
};

class Install : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::scratch_dir("install");
    prefix = dir / "moved";
    fs::copy(installed_prefix(), prefix, fs::copy_options::recursive);
  }
  // The installed pdrt, with no PDRT_* variable that would point elsewhere.
  InstalledRun pdrt(const std::string& args) {
    const fs::path err = dir / "err.txt";
    const std::string cmd = "env -u PDRT_TABLES -u PDRT_ASSETS -u PDRT_IMAGE_MODULE '" +
                            (prefix / "bin" / "pdrt").string() + "' " + args + " >/dev/null 2>'" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    std::stringstream ss;
    ss << std::ifstream(err).rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
  }
  std::string render_env_lit() {
    return "render '" + (prefix / "share/pdrt/scenes/env-lit.json").string() +
           "' --spp 1 --width 16 --height 12 -q -o '" + (dir / "o.png").string() + "'";
  }
  fs::path dir, prefix;
};

TEST_F(Install, MovedInstallRendersTheDemoSceneAndTheSkyScene) {
  for (const char* scene : {"cornell-box.json", "env-lit.json"}) {
    InstalledRun r = pdrt("render '" + (prefix / "share/pdrt/scenes" / scene).string() +
                          "' --spp 1 --width 16 --height 12 -q -o '" + (dir / "o.png").string() + "'");
    EXPECT_EQ(r.code, 0) << scene << ": " << r.err;
    EXPECT_TRUE(fs::exists(dir / "o.png")) << scene;
    fs::remove(dir / "o.png");
  }
  for (const char* doc : {"share/doc/pdrt/README.md", "share/doc/pdrt/docs/sampling.md"})
    EXPECT_TRUE(fs::exists(prefix / doc)) << doc;
}

TEST_F(Install, InstalledPdrtReadsTheInstalledTables) {
  const fs::path table = prefix / "share/pdrt/tables/pixel.pdrttbl";
  fs::resize_file(table, 16);
  InstalledRun r = pdrt(render_env_lit());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find(table.string()), std::string::npos) << r.err;
}

TEST_F(Install, InstalledPdrtLoadsTheInstalledImageModule) {
  const fs::path module = prefix / "lib/pdrt/libpdrt_image.so";
  ASSERT_TRUE(fs::exists(module));
  std::ofstream(module, std::ios::trunc) << "not a shared object";
  InstalledRun r = pdrt(render_env_lit());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("cannot load the image module " + module.string()), std::string::npos) << r.err;
}

TEST_F(Install, InstalledPdrtFindsTheInstalledSky) {
  const fs::path sky = prefix / "share/pdrt/assets/sky.exr";
  std::ofstream(sky, std::ios::trunc) << "not an image";
  InstalledRun r = pdrt(render_env_lit());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("sky.exr"), std::string::npos) << r.err;
}

TEST_F(Install, InstalledPdrtRunsTheInstalledPlotScript) {
  const fs::path script = prefix / "share/pdrt/scripts/plot_analysis.py";
  std::ofstream(script, std::ios::trunc) << "import sys\nsys.exit(3)\n";
  std::ofstream(dir / "p.csv") << "x0,x1\n0.1,0.2\n0.6,0.7\n0.3,0.9\n";
  InstalledRun r = pdrt("analyze '" + (dir / "p.csv").string() + "' -q -o '" + (dir / "a").string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find(script.string()), std::string::npos) << r.err;
}

// The commands a plan prints run as printed: the installed pdrt by its absolute path.
TEST_F(Install, PlanPrintsCommandsThatRunTheInstalledPdrt) {
  const fs::path scene = prefix / "share/pdrt/scenes/cornell-box.json";
  InstalledRun r = pdrt("compare '" + scene.string() + "' --plan '" + (dir / "plan").string() +
                        "' --samplers jitter --spp 1 --seeds 1 --reference-spp 4 --width 8 --height 8");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string self = (prefix / "bin" / "pdrt").string();
  EXPECT_NE(r.err.find(self + " run-job " + (dir / "plan").string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("`" + self + " collect " + (dir / "plan").string() + "`"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace pdrt
