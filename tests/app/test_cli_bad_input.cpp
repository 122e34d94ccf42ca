// Classes of bad input an independent corpus found: strict numeric options (one range for the
// command line and the scene file), cost limits, and messages that name the thing and where.
#include "tests/support/cli_runner.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

namespace pdrt {
namespace {

namespace fs = std::filesystem;
using test::run_pdrt;

fs::path write_scene(const fs::path& dir, const std::string& film = R"("width": 24, "height": 16)") {
  fs::path p = dir / "scene.json";
  std::ofstream(p) << "{\n  \"camera\": {\"position\": [0, 0, 4], \"look_at\": [0, 0, 0]},\n  \"film\": {" << film
                   << "},\n  \"materials\": {\"grey\": {\"type\": \"diffuse\"}},\n"
                      "  \"objects\": [{\"type\": \"sphere\", \"material\": \"grey\", \"radius\": 1}]\n}\n";
  return p;
}

// The given exit code, one line on stderr containing `what`, and no output left behind.
void expect_refused(const std::string& args, const fs::path& out, int code, const std::string& what) {
  auto r = run_pdrt(args);
  EXPECT_EQ(r.exit_code, code) << args << "\n" << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << args << "\n" << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << args << ": message should contain " << what << ": " << r.err;
  EXPECT_FALSE(fs::exists(out)) << args;
}

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override { dir = test::scratch_dir("bad_input"); }
  fs::path dir;
};

TEST_F(BadInput, IntegerOptionsRefuseNegativeHugeFractionalAndExponentText) {
  fs::path scene = write_scene(dir), out = dir / "o.exr";
  const std::string render = "render " + scene.string() + " -o " + out.string() + " -q ";
  for (const char* opt : {"--seed", "--spp", "--width", "--threads", "--min-spp"})
    for (const char* v : {"-1", "18446744073709551616", "1e23", "2.5"})
      expect_refused(render + opt + " " + v, out, 2, std::string(opt) + " must be an integer in [");
  expect_refused(render + "--spp 0", out, 2, "--spp must be an integer in [1, 16777216], got \"0\"");
  expect_refused(render + "--seed -1", out, 2, "(negative)");
  expect_refused(render + "--seed 18446744073709551616", out, 2, "(out of range)");
}

TEST_F(BadInput, OtherSubcommandsParseIntegersStrictly) {
  expect_refused("tables --seed -1 -o " + (dir / "t").string(), dir / "t", 2, "--seed must be an integer in [0, ");
  expect_refused("sample -m random -n 2.5 -o " + (dir / "p.csv").string(), dir / "p.csv", 2, "--count");
  expect_refused("sample -m random -n 10 --seed 1e23 -o " + (dir / "p.csv").string(), dir / "p.csv", 2, "--seed");
  expect_refused("compare " + write_scene(dir).string() + " -o " + (dir / "c").string() + " --spp 1,-4", dir / "c", 2,
                 "--spp must be an integer in [1, 16777216], got \"-4\"");
  expect_refused("compare " + write_scene(dir).string() + " -o " + (dir / "c").string() + " --reference-spp 1e23",
                 dir / "c", 2, "--reference-spp");
}

TEST_F(BadInput, AnalyzeResolutionZeroIsRefusedWithTheRange) {
  fs::path csv = dir / "p.csv";
  ASSERT_EQ(run_pdrt("sample -m random -n 64 -q -o " + csv.string()).exit_code, 0);
  expect_refused("analyze --no-plots -q --resolution 0 -o " + (dir / "a").string() + " " + csv.string(),
                 dir / "a" / "stats.json", 2, "--resolution must be an even number from 32 to 4096");
}

TEST_F(BadInput, HugeSppIsRefusedAboveTheSharedMaximum) {
  fs::path scene = write_scene(dir), out = dir / "o.exr";
  expect_refused("render " + scene.string() + " -o " + out.string() + " --spp 2000000000", out, 2,
                 "--spp must be an integer in [1, 16777216]");
}

// The budget is in time, timed on the scene (render_estimate.h): 1.7e13 samples are over it on
// any machine (46 min is 2.7 ns per sample), and --time-limit bounds a render instead.
TEST_F(BadInput, RenderOverTheSampleBudgetIsRefusedUnlessAllowed) {
  fs::path scene = write_scene(dir, R"("width": 1000, "height": 1000)"), out = dir / "o.exr";
  expect_refused("render " + scene.string() + " -o " + out.string() + " --spp 16777216", out, 2,
                 "1000x1000 pixels x 16777216 spp = 1.68e+13 samples (about ");
  expect_refused("render " + scene.string() + " -o " + out.string() + " --spp 16777216", out, 2,
                 "measured on this scene), more than the limit of 46 min");
  auto limited = run_pdrt("render " + scene.string() + " -o " + out.string() + " --spp 16777216 --time-limit 1e-6 -q");
  EXPECT_EQ(limited.exit_code, 0) << "a time limit bounds the render: " << limited.err;
  auto r = run_pdrt("render " + scene.string() + " -o " + out.string() +
                    " --spp 16000 --allow-long-render"
                    " --width 2 --height 2 -q");
  EXPECT_EQ(r.exit_code, 0) << "small enough once --width/--height shrink it: " << r.err;
}

TEST_F(BadInput, CompareCountsEveryRenderAgainstTheBudget) {
  fs::path scene = write_scene(dir, R"("width": 2000, "height": 1000)");
  expect_refused("compare " + scene.string() + " -o " + (dir / "c").string() + " --no-plots --reference-spp 4096",
                 dir / "c" / "results.json", 2, "more than the limit of 46 min");
}

TEST_F(BadInput, TimeLimitMustBeAPositiveNumber) {
  fs::path scene = write_scene(dir), out = dir / "o.exr";
  const std::string render = "render " + scene.string() + " -o " + out.string() + " -q --time-limit ";
  for (const char* v : {"0", "-1", "-0.5"}) expect_refused(render + v, out, 2, "--time-limit must be > 0, got");
  for (const char* v : {"abc", "1s", "nan", "inf", "''"})
    expect_refused(render + v, out, 2, "--time-limit must be a finite number, got");
}

TEST_F(BadInput, RenderSaysWhatItWillCostBeforeStarting) {
  fs::path scene = write_scene(dir);
  auto r = run_pdrt("render " + scene.string() + " -o " + (dir / "o.exr").string() + " --spp 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("24x16 pixels x 4 spp = 1.54e+03 samples"), std::string::npos) << r.err;
}

TEST_F(BadInput, FilmTooLargeNamesTheSceneKeyOrTheOptions) {
  fs::path scene = write_scene(dir, R"("width": 65536, "height": 65536)"), out = dir / "o.exr";
  expect_refused("render " + scene.string() + " -o " + out.string(), out, 1,
                 "scene.json:3:21: film.width/height: film");
  fs::path small = dir / "small";
  fs::create_directories(small);
  fs::path s2 = write_scene(small);
  expect_refused("render " + s2.string() + " -o " + out.string() + " --width 65536 --height 65536", out, 1,
                 "--width/--height: film 65536x65536 needs");
}

TEST_F(BadInput, UnknownSubcommandIsNamed) {
  auto r = run_pdrt("frob");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown subcommand \"frob\" (expected sample, analyze, tables, render, compare"),
            std::string::npos)
      << r.err;
}

// Issue 29: CLI11 listed extras reversed ("16 --sampls") with no suggestion.
TEST_F(BadInput, UnknownOptionsAreNamedInTheOrderTypedWithTheNearestValidOption) {
  fs::path scene = write_scene(dir);
  const fs::path out = dir / "o.png";
  expect_refused(
      "render " + scene.string() + " -o " + out.string() + " --sampls 16 --seeed 3 --zzzzzz", out, 2,
      "render: unknown options --sampls (did you mean --sampler?), --seeed (did you mean --seed?), --zzzzzz");
  expect_refused("compare " + scene.string() + " --out " + (dir / "c").string() + " --sampler=sobol", dir / "c", 2,
                 "compare: unknown option --sampler (did you mean --samplers?)");
}

TEST_F(BadInput, UnexpectedPositionalArgumentsAreNamedInTheOrderTyped) {
  fs::path scene = write_scene(dir);
  const fs::path out = dir / "o.png";
  expect_refused("render " + scene.string() + " -o " + out.string() + " first second", out, 2,
                 "render: unexpected arguments \"first\" \"second\"");
}

TEST_F(BadInput, EmptyOutputPathNamesTheOption) {
  fs::path scene = write_scene(dir);
  for (const std::string& args :
       std::vector<std::string>{"render " + scene.string() + " -o ''", std::string("sample -m random -n 4 -o ''"),
                                std::string("tables -o ''"), "compare " + scene.string() + " -o ''"})
    expect_refused(args, dir / "none", 2, "-o/--out: empty path");
}

TEST_F(BadInput, DirectoriesAndMissingFilesAreNamedWithTheReason) {
  fs::create_directories(dir / "d");
  expect_refused("analyze --no-plots -o " + (dir / "a").string() + " " + (dir / "d").string(), dir / "a" / "stats.json",
                 1, "cannot open: Is a directory");
  expect_refused("analyze --no-plots -o " + (dir / "a").string() + " --table " + (dir / "d").string(),
                 dir / "a" / "stats.json", 1, "cannot open: Is a directory");
  expect_refused("analyze --no-plots -o " + (dir / "a").string() + " " + (dir / "missing.csv").string(),
                 dir / "a" / "stats.json", 1, "missing.csv: cannot open: No such file or directory");
}

// Point, spot and distant lights (issue 17): a bad value or an unknown key is one line naming
// file:line:col and the key, exit status 1, and no image written.
TEST_F(BadInput, BadDeltaLightsAreRefusedByNameWithoutOutput) {
  const fs::path out = dir / "o.png";
  struct Case {
    const char* light;
    const char* what;
  };
  const Case cases[] = {
      {R"({"type": "point", "position": [0, 2, 0], "intensity": [1, -2, 1]})",
       "scene.json:7:59: lights[0].intensity must have components >= 0, got [1,-2,1]"},
      {R"({"type": "spot", "intensity": [1, 1, 1], "direction": [0, 0, 0]})",
       "scene.json:7:59: lights[0].direction must be non-zero, got [0,0,0]"},
      {R"({"type": "distant", "direction": [0, 0, 0], "irradiance": [1, 1, 1]})",
       "scene.json:7:38: lights[0].direction must be non-zero"},
      {R"({"type": "spot", "intensity": [1, 1, 1], "direction": [0, -1, 0], "cone_angle_deg": 0})",
       "scene.json:7:89: lights[0].cone_angle_deg must be in (0, 180]"},
      {R"({"type": "spot", "intensity": [1, 1, 1], "direction": [0, -1, 0], "cone_angle_deg": 200})",
       "lights[0].cone_angle_deg must be in (0, 180] (degrees from the axis to the cone's edge), got 200"},
      {R"({"type": "point", "intensity": [1, 1, 1], "colour": [1, 1, 1]})",
       "scene.json:7:47: lights[0].colour unknown key"},
      {R"({"type": "distant", "direction": [0, -1, 0], "irradiance": [1, 1, 1], "intensity": 2})",
       "lights[0].intensity unknown key"},
  };
  for (const Case& c : cases) {
    const fs::path scene = dir / "scene.json";
    std::ofstream(scene) << "{\n  \"camera\": {\"position\": [0, 0, 4], \"look_at\": [0, 0, 0]},\n"
                            "  \"film\": {\"width\": 8, \"height\": 8},\n"
                            "  \"materials\": {\"grey\": {\"type\": \"diffuse\"}},\n"
                            "  \"objects\": [{\"type\": \"sphere\", \"material\": \"grey\", \"radius\": 1}],\n"
                            "  \"lights\": [\n"
                            "    "
                         << c.light << "\n  ]\n}\n";
    expect_refused("render " + scene.string() + " -q -o " + out.string(), out, 1, c.what);
  }
}

TEST_F(BadInput, InvalidBytesInAFileNameAreEscaped) {
  auto r = run_pdrt("analyze --no-plots -o " + (dir / "a").string() + " \"$(printf '\\377\\033[31m.csv')\"");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("\\xFF\\x1B[31m.csv: cannot open"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace pdrt
