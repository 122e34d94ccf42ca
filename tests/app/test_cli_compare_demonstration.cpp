// `pdrt compare`'s demonstration sheet and blurred-error heat maps (issue 31 item 5): drawn by
// default for a small comparison with the size its layout gives, named in results.json;
// --demo-crop moves its square; bad --demo-crop is refused before rendering.
#include "tests/support/cli_runner.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace fs = std::filesystem;
using namespace pdrt::test;
using nlohmann::json;

namespace {

fs::path write_scene(const fs::path& dir) {
  fs::path p = dir / "scene.json";
  std::ofstream(p) << R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 40, "height": 32},
  "materials": {"grey": {"type": "diffuse"}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1}],
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
}
)";
  return p;
}

const std::string kOptions = " --samplers jitter,poisson,sobol --seeds 2 --reference-spp 32 --no-plots -q";
const std::string kSmall = kOptions + " --spp 1,2";

std::array<int, 2> png_size(const fs::path& p) {
  auto in = OIIO::ImageInput::open(p.string());
  if (!in) return {0, 0};
  return {in->spec().width, in->spec().height};
}

// The exit code, one line on stderr containing `what`, and no report directory.
void expect_refused(const std::string& args, const fs::path& out, const std::string& what) {
  const CliResult r = run_pdrt(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  EXPECT_EQ(line_count(r.err), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << args << ": should contain " << what << ": " << r.err;
  EXPECT_FALSE(fs::exists(out)) << args;
}

}  // namespace

// 3 samplers x 2 spp of the 8-pixel detail window (min(40, 32) / 4), zoomed 12x to 96 pixels:
// 222 + 204 x 2 by 111 + 102 x 3 pixels (tests/renderer/compare/test_demonstration_sheet.cpp).
TEST(CliCompareDemonstration, SmallCompareWritesTheSheetAndBlurredMaps) {
  const fs::path d = scratch_dir("compare_demo");
  const fs::path out = d / "r";
  const CliResult r = run_pdrt("compare " + write_scene(d).string() + " -o " + out.string() + kSmall + " --cache-dir " +
                               (d / "c").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(std::ifstream(out / "results.json"));
  ASSERT_TRUE(j["demonstration"].is_object());
  EXPECT_EQ(j["demonstration"]["file"], "images/demonstration.png");
  EXPECT_EQ(j["demonstration"]["crop"]["size"], 8);
  EXPECT_EQ(j["demonstration"]["crop"]["zoom"], 12);
  EXPECT_EQ(png_size(out / "images" / "demonstration.png"), (std::array<int, 2>{222 + 204 * 2, 111 + 102 * 3}));
  EXPECT_EQ(j["blurred_error_maps"]["sigma"], 1.0);
  for (const json& u : j["runs"]) {
    const std::string f = u["blurred_error_map"];
    EXPECT_EQ(png_size(out / f), (std::array<int, 2>{40, 32})) << f;
  }
}

TEST(CliCompareDemonstration, DemoCropNamesTheSquare) {
  const fs::path d = scratch_dir("compare_demo_crop");
  const fs::path out = d / "r";
  const CliResult r = run_pdrt("compare " + write_scene(d).string() + " -o " + out.string() + kSmall +
                               " --demo-crop 4,6,24 --cache-dir " + (d / "c").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(std::ifstream(out / "results.json"));
  const json& c = j["demonstration"]["crop"];
  EXPECT_EQ(c["x"], 4);
  EXPECT_EQ(c["y"], 6);
  EXPECT_EQ(c["size"], 24);
  EXPECT_EQ(c["zoom"], 4);
  EXPECT_EQ(j["demonstration"]["crop_rule"], "--demo-crop");
  EXPECT_EQ(png_size(out / "images" / "demonstration.png"), (std::array<int, 2>{222 + 204 * 2, 111 + 102 * 3}));
}

TEST(CliCompareDemonstration, BadDemoCropIsRefusedBeforeRendering) {
  const fs::path d = scratch_dir("compare_demo_bad");
  const std::string head = "compare " + write_scene(d).string() + " -o " + (d / "r").string() + kSmall;
  expect_refused(head + " --demo-crop 20,0,24", d / "r",
                 "--demo-crop 20,0,24: the square leaves the 40x32 image (x + side <= 40, y + side <= 32)");
  expect_refused(head + " --demo-crop 0,10,24", d / "r", "the square leaves the 40x32 image");
  expect_refused(head + " --demo-crop 0,0,0", d / "r", "--demo-crop 0,0,0: the side must be >= 1");
  expect_refused(head + " --demo-crop 1,2", d / "r", "--demo-crop: give x,y,size (three integers, pixels)");
  expect_refused(head + " --demo-crop 1,2,3,4", d / "r", "--demo-crop: give x,y,size");
  expect_refused(head + " --demo-crop=-1,0,8", d / "r", "--demo-crop must be an integer in [0, 65536]");
  expect_refused("compare " + write_scene(d).string() + " -o " + (d / "r").string() + kOptions +
                     " --demo-crop 0,0,8 --spp 1,2,3,4,5,6,7",
                 d / "r", "the demonstration sheet is drawn for at most 8 samplers and 6 sample counts, got 3 and 7");
  // The film's crop window makes the image smaller: the square must fit that.
  expect_refused(head + " --demo-crop 0,0,24 --width 20", d / "r", "leaves the 20x32 image");
}
