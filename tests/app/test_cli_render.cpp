// `pdrt render` and `pdrt compare` from the command line: outputs, metadata, bad input.
#include "tests/support/cli_runner.h"
#include "tests/support/one_cpu.h"
#include "tests/support/terminal_child.h"
#include "renderer/image/image_output.h"
#include "sampling/analysis/stream_analysis.h"
#include "sampling/samplers/sampler.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <nlohmann/json.hpp>

using namespace pdrt;
using pdrt::test::run_pdrt;
using pdrt::test::scratch_dir;
namespace fs = std::filesystem;

namespace {

fs::path write_scene(const fs::path& dir, const std::string& film = R"("width": 24, "height": 16)") {
  fs::path p = dir / "scene.json";
  std::ofstream(p) << R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {)" << film
                   << R"(},
  "sampler": {"spp": 4},
  "materials": {"grey": {"type": "glossy", "albedo": [0.8, 0.8, 0.8], "roughness": 0.4}},
  "objects": [{"type": "sphere", "material": "grey", "radius": 1}],
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
}
)";
  return p;
}

// `pdrt compare SCENE --out DIR/OUT --cache-dir DIR/cache ARGS`: its result, and its
// results.json when it wrote one (else null).
struct CompareRun {
  pdrt::test::CliResult cli;
  nlohmann::json results;
};
CompareRun run_compare(const fs::path& dir, const fs::path& scene, const std::string& args,
                       const std::string& out = "report") {
  CompareRun c{run_pdrt("compare '" + scene.string() + "' --out " + (dir / out).string() + " --cache-dir " +
                        (dir / "cache").string() + " " + args),
               nullptr};
  if (fs::exists(dir / out / "results.json"))
    c.results = nlohmann::json::parse(std::ifstream(dir / out / "results.json"));
  return c;
}
}  // namespace

TEST(CliRender, WritesExrWithAovsMetadataAndStats) {
  fs::path d = scratch_dir("render_exr");
  fs::path scene = write_scene(d);
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() + " --spp 3 --seed 5 --stats " +
                    (d / "stats.json").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto in = OIIO::ImageInput::open((d / "out.exr").string());
  ASSERT_TRUE(in);
  const auto& spec = in->spec();
  EXPECT_EQ(spec.width, 24);
  EXPECT_EQ(spec.nchannels, 12);
  for (const char* c : {"samples", "variance", "albedo.R", "N.X", "Z"})
    EXPECT_NE(std::find(spec.channelnames.begin(), spec.channelnames.end(), c), spec.channelnames.end()) << c;
  EXPECT_EQ(spec.get_string_attribute("pdrt:sampler"), "poisson");
  EXPECT_EQ(spec.get_string_attribute("pdrt:spp"), "3");
  EXPECT_EQ(spec.get_string_attribute("pdrt:seed"), "5");
  EXPECT_EQ(spec.get_string_attribute("pdrt:partial"), "false");
  nlohmann::json j = nlohmann::json::parse(std::ifstream(d / "stats.json"));
  for (const char* k : {"seconds", "rays", "mrays_per_second", "samples", "spp_mean", "cpu_seconds", "sampler_share"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_GT(j["rays"].get<int64_t>(), 0);
  const auto& share = j["sampler_share"];
  EXPECT_GE(share["ticks"].get<int64_t>(), share["sampler_ticks"].get<int64_t>());
  EXPECT_EQ(share["share"].is_null(), share["ticks"].get<int64_t>() == 0) << share.dump();
}

// Issue 29: `-o /nonexistent-dir/sub/t.png` created the directories without a word.
TEST(CliRender, CreatedOutputDirectoryIsReportedOnStderr) {
  fs::path d = scratch_dir("render_mkdir");
  fs::path scene = write_scene(d);
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "new" / "sub" / "t.png").string() + " --spp 1 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(
      r.err.find("pdrt: created directory '" + (d / "new").string() + "' for '" + (d / "new" / "sub").string() + "'"),
      std::string::npos)
      << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  // Writing into it again creates nothing and says nothing.
  r = run_pdrt("render " + scene.string() + " -o " + (d / "new" / "sub" / "t.png").string() + " --spp 1 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

// The spp asked for is what is traced and what every report says: the summary line, the
// stats and the samples AOV (the old default traced about 50 of 64 and printed "50.0 spp").
TEST(CliRender, SppAskedForIsTracedAndReportedInEveryMode) {
  fs::path d = scratch_dir("render_spp");
  fs::path scene = write_scene(d);
  for (const char* mode : {"importance", "splat"}) {
    fs::path stats = d / (std::string(mode) + ".json");
    auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() + " --spp 64 --reconstruction " +
                      mode + " --stats " + stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(", 64.0 spp, "), std::string::npos) << r.err;
    nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
    EXPECT_EQ(j["spp_mean"].get<double>(), 64.0) << mode;
    EXPECT_EQ(j["reconstruction"].get<std::string>(), mode);
    auto in = OIIO::ImageInput::open((d / "out.exr").string());
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_string_attribute("pdrt:reconstruction"), mode);
  }
}

TEST(CliRender, UnknownReconstructionIsAUsageError) {
  fs::path d = scratch_dir("render_recon_bad");
  fs::path scene = write_scene(d);
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() + " --reconstruction weights");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--reconstruction: unknown mode \"weights\" (importance, splat, rank)"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(d / "out.exr"));
  r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() +
               " --reconstruction rank --adaptive-decision split");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("adaptive decision \"split\" needs reconstruction"), std::string::npos) << r.err;
}

// The split-with-rank refusal in one wording wherever the settings come from: a JSON scene,
// render's and compare's overrides over a JSON scene, and render's over a pbrt scene (the
// overrides share one path, app/scene_overrides.h; the validator is renderer/scene/render_settings.h).
TEST(CliRender, SplitWithRankIsRefusedInOneWordingFromEveryEntry) {
  const std::string words = "\"split\" needs reconstruction \"importance\" or \"splat\", not \"rank\"";
  fs::path d = scratch_dir("render_split_rank");
  fs::path in_file = d / "split.json";
  std::ofstream(in_file) << R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 24, "height": 16, "filter": {"reconstruction": "rank"}},
  "sampler": {"spp": 4, "adaptive": {"decision": "split"}},
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
}
)";
  auto r = run_pdrt("render " + in_file.string() + " -o " + (d / "a.exr").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("sampler.adaptive.decision " + words), std::string::npos) << r.err;
  fs::path plain = write_scene(d);
  fs::path pbrt = d / "s.pbrt";
  std::ofstream(pbrt) << "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\n"
                         "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n"
                         "LightSource \"infinite\" \"rgb L\" [1 1 1]\n";
  const std::string overrides = " --reconstruction rank --adaptive-decision split";
  for (const std::string& command :
       {"render " + plain.string() + " -o " + (d / "b.exr").string() + overrides,
        "render " + pbrt.string() + " -o " + (d / "c.exr").string() + overrides,
        "compare " + plain.string() + " --out " + (d / "cmp").string() + " --no-plots --adaptive" + overrides}) {
    r = run_pdrt(command);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("adaptive decision " + words), std::string::npos) << command << ": " << r.err;
  }
}

// `poisson-ip` without splatting, with adaptive refinement or past its pattern's spp is refused
// before rendering in one line, nothing written: at sampler.type in a scene file (exit 1), as
// a usage error when render's or compare's options make the combination (exit 2).
TEST(CliRender, ImagePlaneSamplerRefusesWhatItCannotServe) {
  const std::string needs =
      "sampler \"poisson-ip\" needs reconstruction \"splat\" (its pixels take varying counts of one image-plane "
      "pattern's samples), got \"importance\"";
  fs::path d = scratch_dir("render_image_plane");
  fs::path in_file = d / "ip.json";
  std::ofstream(in_file) << R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 24, "height": 16},
  "sampler": {"type": "poisson-ip", "spp": 4},
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
}
)";
  auto r = run_pdrt("render " + in_file.string() + " -o " + (d / "a.exr").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err, "pdrt: " + in_file.string() + ":4:23: sampler.type: " + needs + "\n");
  fs::path plain = write_scene(d);
  const std::string adaptive =
      "sampler \"poisson-ip\" cannot refine adaptively (its pixels' samples are one image-plane pattern's, whose "
      "counts a pixel cannot raise alone)";
  const std::pair<std::string, std::string> cases[] = {
      {"render " + plain.string() + " -o " + (d / "b.exr").string() + " --sampler poisson-ip", needs},
      {"render " + plain.string() + " -o " + (d / "b.exr").string() +
           " --sampler poisson-ip --reconstruction splat --adaptive",
       adaptive},
      {"render " + plain.string() + " -o " + (d / "b.exr").string() +
           " --sampler poisson-ip --reconstruction splat --spp 70000",
       "sampler \"poisson-ip\" takes at most 65536 spp (the points of its image-plane pattern), got 70000"},
      {"compare " + plain.string() + " --out " + (d / "cmp").string() + " --no-plots --samplers poisson,poisson-ip",
       "--samplers/--spp: sampler " + needs.substr(8)},
      {"render " + plain.string() + " -o " + (d / "b.exr").string() + " --sampler poisson-xx", ""}};
  for (const auto& [command, words] : cases) {
    r = run_pdrt(command);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_EQ(pdrt::test::line_count(r.err), 1) << r.err;
    if (!words.empty()) {
      EXPECT_EQ(r.err, "pdrt: " + words + "\n") << command;
    }
  }
  EXPECT_FALSE(fs::exists(d / "a.exr"));
  EXPECT_FALSE(fs::exists(d / "b.exr"));
  EXPECT_FALSE(fs::exists(d / "cmp"));
}

// "threads" is the count the render ran on: --threads 0 (the default) means all of them.
TEST(CliRender, StatsReportTheThreadsUsedNotTheOption) {
  fs::path d = scratch_dir("render_threads");
  fs::path scene = write_scene(d);
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "a.exr").string() + " --spp 1 --stats " +
                    (d / "all.json").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_pdrt("render " + scene.string() + " -o " + (d / "b.exr").string() + " --spp 1 --threads 1 --stats " +
               (d / "one.json").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json all = nlohmann::json::parse(std::ifstream(d / "all.json"));
  nlohmann::json one = nlohmann::json::parse(std::ifstream(d / "one.json"));
  EXPECT_GE(all["threads"].get<int>(), 1);
  EXPECT_EQ(one["threads"].get<int>(), 1);
}

namespace {

// Renders the test scene restricted to one CPU (as under mpirun's default binding) with
// `options`; returns the run and its --stats.
std::pair<test::CliResult, nlohmann::json> render_on_one_cpu(const std::string& name, const std::string& options) {
  fs::path d = scratch_dir(name);
  fs::path scene = write_scene(d);
  test::OneCpu one;
  EXPECT_TRUE(one.ok());
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "a.exr").string() + " --spp 1 --stats " +
                    (d / "s.json").string() + " --quiet" + options);
  nlohmann::json j = r.exit_code == 0 ? nlohmann::json::parse(std::ifstream(d / "s.json")) : nlohmann::json{};
  return {r, j};
}

}  // namespace

// A process allowed one CPU asked for 2 threads says so once (with the options that fix it),
// still renders, on the one CPU, and --stats records both counts.
TEST(CliRender, ThreadsAboveTheAffinityMaskWarnOnceAndRunOnTheAllowedCpus) {
  const auto [r, j] = render_on_one_cpu("render_affinity", " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  for (const char* part : {"--threads 2", "1 CPU", "--bind-to none", "--map-by slot:PE=2"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << " in " << r.err;
  EXPECT_EQ(j["cpus_allowed"].get<int>(), 1);
  EXPECT_EQ(j["threads"].get<int>(), 1);
}

// Without --threads the render takes the CPUs of its mask (TBB's default arena), silently.
TEST(CliRender, DefaultThreadsAreTheAffinityMasksCpus) {
  const auto [r, j] = render_on_one_cpu("render_affinity_default", "");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(j["cpus_allowed"].get<int>(), 1);
  EXPECT_EQ(j["threads"].get<int>(), 1);
}

TEST(CliRender, PngIsSrgbAndCommandLineOverridesTheScene) {
  fs::path d = scratch_dir("render_png");
  fs::path scene = write_scene(d);
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.png").string() +
                    " --width 10 --height 6 --sampler jitter --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto in = OIIO::ImageInput::open((d / "out.png").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 10);
  EXPECT_EQ(in->spec().height, 6);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
}

TEST(CliRender, BadArgumentsAreRefusedBeforeRendering) {
  fs::path d = scratch_dir("render_bad");
  fs::path scene = write_scene(d);
  const std::string out = (d / "out.exr").string();
  struct Case {
    std::string args, needle;
    int code;
  } cases[] = {
      {"--spp 0", "--spp", 2},
      {"--sampler halton", "halton", 2},
      {"--width -3", "--width", 2},
      {"--threads -1", "--threads", 2},
      {"--min-spp 0", "--min-spp", 2},
      {"--adaptive-threshold -1", "--adaptive-threshold", 2},
      {"--adaptive-metric foo", "foo", 2},
      {"--adaptive-variance foo", "foo", 2},
      {"--adaptive-decision foo", "--adaptive-decision must be one of shared, split, got \"foo\"", 2},
      {"--min-spp 8 --max-spp 4", "min_spp", 2},
  };
  for (const auto& c : cases) {
    auto r = run_pdrt("render " + scene.string() + " -o " + out + " " + c.args);
    EXPECT_EQ(r.exit_code, c.code) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << r.err;
    EXPECT_EQ(pdrt::test::line_count(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.bmp").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  std::ofstream(d / "a-file") << "not a directory";
  r = run_pdrt("render " + scene.string() + " -o " + (d / "a-file" / "out.exr").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(pdrt::test::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("a-file"), std::string::npos) << r.err;
  r = run_pdrt("render " + (d / "nope.json").string() + " -o " + out);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

namespace {
// The 8-bit RGB values of an image file; EXR values are converted to sRGB and quantised as
// pdrt does for PNG.
std::vector<int> srgb8(const fs::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  EXPECT_TRUE(in) << file;
  if (!in) return {};
  const auto& spec = in->spec();
  std::vector<float> px(std::size_t(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
  const bool linear = spec.format == OIIO::TypeDesc::FLOAT;
  std::vector<int> out;
  for (std::size_t i = 0; i < px.size(); i += spec.nchannels)
    for (int c = 0; c < 3; ++c) {
      float v = linear ? linear_to_srgb(px[i + c]) : px[i + c];
      out.push_back(int(std::lround(v * 255.0f)));
    }
  return out;
}
}  // namespace

TEST(CliRender, OneRenderWritesEveryRequestedFormatWithTheSamePixels) {
  fs::path d = scratch_dir("render_two_outputs");
  fs::path scene = write_scene(d);
  const std::string common = " --spp 3 --seed 9 --quiet";
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "both.exr").string() + " -o " +
                    (d / "both.png").string() + common);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_pdrt("render " + scene.string() + " -o " + (d / "alone.png").string() + common);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<int> png = srgb8(d / "both.png");
  ASSERT_EQ(png.size(), std::size_t(24 * 16 * 3));
  EXPECT_EQ(png, srgb8(d / "alone.png")) << "the PNG of a two-output render is the PNG of its own render";
  EXPECT_EQ(png, srgb8(d / "both.exr")) << "the PNG is the EXR of the same render in sRGB";
}

TEST(CliRender, BadSecondOutputIsRefusedBeforeRenderingLeavingNoFile) {
  fs::path d = scratch_dir("render_bad_second");
  fs::path scene = write_scene(d);
  std::ofstream(d / "a-file") << "not a directory";
  const fs::path good = d / "good.exr";
  struct Case {
    std::string second;
    int code;
  } cases[] = {{(d / "out.bmp").string(), 2}, {(d / "a-file" / "out.png").string(), 1}, {good.string(), 2}};
  for (const auto& c : cases) {
    auto r = run_pdrt("render " + scene.string() + " -o " + good.string() + " -o " + c.second + " --spp 64 --quiet");
    EXPECT_EQ(r.exit_code, c.code) << c.second << ": " << r.err;
    EXPECT_EQ(pdrt::test::line_count(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(good)) << c.second;
  }
}

TEST(CliRender, AdaptiveFlagsRefineAndStatsReportTheSppDistribution) {
  fs::path d = scratch_dir("render_adaptive");
  fs::path scene = write_scene(d);
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() +
                    " --min-spp 2 --max-spp 16 --adaptive-metric contrast --stats " + (d / "stats.json").string() +
                    " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(std::ifstream(d / "stats.json"));
  ASSERT_TRUE(j.contains("adaptive")) << j.dump();
  EXPECT_EQ(j["adaptive"]["min_spp"], 2);
  EXPECT_EQ(j["adaptive"]["max_spp"], 16);
  EXPECT_EQ(j["adaptive"]["metric"], "contrast");
  EXPECT_DOUBLE_EQ(j["adaptive"]["threshold"].get<double>(), 0.4);  // the metric's own default
  const auto& dist = j["spp_distribution"];
  EXPECT_LE(dist["max"].get<double>(), 16.0);
  EXPECT_LE(dist["min"].get<double>(), dist["p50"].get<double>());
  int64_t pixels = 0;
  for (const auto& b : dist["histogram"]) pixels += b["pixels"].get<int64_t>();
  EXPECT_EQ(pixels, j["width"].get<int64_t>() * j["height"].get<int64_t>());
}

// --spp alone asks for that many samples in every pixel, also of a scene that refines
// adaptively (env-lit does), and says so; an adaptive option keeps the scene's refinement.
TEST(CliRender, SppAloneRendersUniformlyOverAnAdaptiveSceneAndSaysSo) {
  fs::path d = scratch_dir("render_spp_over_adaptive");
  fs::path scene = d / "adaptive.json";
  std::ofstream(scene) << R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 12, "height": 8},
  "sampler": {"spp": 4, "adaptive": {"min_spp": 2, "max_spp": 64, "threshold": 0.001}},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
  "materials": {"m": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
}
)";
  const fs::path stats = d / "stats.json";
  auto r =
      run_pdrt("render " + scene.string() + " --spp 3 -q -o " + (d / "a.exr").string() + " --stats " + stats.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("pdrt render: --spp 3 renders that many samples in every pixel: the scene's adaptive "
                       "refinement (sampler.adaptive) is off; --adaptive keeps it"),
            std::string::npos)
      << r.err;
  nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_FALSE(j.contains("adaptive")) << j.dump();
  EXPECT_EQ(j["samples"].get<int64_t>(), 12 * 8 * 3);
  r = run_pdrt("render " + scene.string() + " --spp 3 --adaptive -q -o " + (d / "b.exr").string() + " --stats " +
               stats.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("--spp 3 renders"), std::string::npos) << r.err;
  j = nlohmann::json::parse(std::ifstream(stats));
  ASSERT_TRUE(j.contains("adaptive")) << j.dump();
  EXPECT_EQ(j["adaptive"]["max_spp"], 64);
  EXPECT_GT(j["samples"].get<int64_t>(), 12 * 8 * 2);  // the threshold keeps most pixels refining
}

TEST(CliRender, FramebufferTooLargeForMemoryIsRefused) {
  fs::path d = scratch_dir("render_huge");
  fs::path scene = write_scene(d, R"("width": 65536, "height": 65536)");
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("GiB"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "out.exr"));
}

TEST(CliCompare, WritesResultsWithErrorsThatFallWithSpp) {
  fs::path d = scratch_dir("compare");
  fs::path scene = write_scene(d);
  auto [r, j] = run_compare(d, scene, "--samplers jitter,poisson --spp 2,8,32 --reference-spp 512 --no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(j["runs"].size(), 6u);
  for (const char* s : {"jitter", "poisson"}) {
    std::vector<double> e;
    for (const auto& run : j["runs"])
      if (run["sampler"] == s) e.push_back(run["rmse"]);
    ASSERT_EQ(e.size(), 3u);
    EXPECT_LT(e[2], e[0]) << s;
    EXPECT_LT(j["slopes"][s].get<double>(), -0.3) << s;
  }
  EXPECT_TRUE(fs::exists(d / "report" / "results.csv"));
  EXPECT_TRUE(fs::exists(d / "report" / "errors" / "poisson-8.png"));
  EXPECT_FALSE(j["reference"]["cached"].get<bool>());
  // The second run reuses the cached reference.
  const CompareRun again =
      run_compare(d, scene, "--samplers jitter --spp 2,8 --reference-spp 512 --no-plots --quiet", "report2");
  ASSERT_EQ(again.cli.exit_code, 0) << again.cli.err;
  EXPECT_TRUE(again.results["reference"]["cached"].get<bool>());
}

// Issue 29: the reference cache key covers every file the scene reads, not only the scene file:
// editing a mesh or a texture image must render a new reference; changing nothing reuses it.
TEST(CliCompare, ReferenceCacheKeySeesTheMeshesAndTexturesTheSceneReads) {
  fs::path d = scratch_dir("compare_inputs");
  std::ofstream(d / "scene.json") << R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 8, "height": 6},
  "textures": {"pic": {"type": "image", "file": "pic.ppm", "filter": "none"}},
  "materials": {"m": {"type": "diffuse", "albedo": "pic"}},
  "objects": [{"type": "obj", "file": "tri.obj", "material": "m"}],
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
}
)";
  auto write_obj = [&](float z) {
    std::ofstream(d / "tri.obj") << "v -1 -1 " << z << "\nv 1 -1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
  };
  auto write_ppm = [&](int grey) {
    std::ofstream(d / "pic.ppm") << "P3\n1 1\n255\n" << grey << " " << grey << " " << grey << "\n";
  };
  write_obj(0);
  write_ppm(200);
  int run = 0;
  auto cached = [&] {
    const CompareRun c =
        run_compare(d, d / "scene.json", "--samplers jitter --spp 2 --reference-spp 16 --no-plots --quiet",
                    "report" + std::to_string(run++));
    EXPECT_EQ(c.cli.exit_code, 0) << c.cli.err;
    return c.results["reference"]["cached"].get<bool>();
  };
  EXPECT_FALSE(cached());
  EXPECT_TRUE(cached()) << "nothing changed";
  write_obj(0.5f);
  EXPECT_FALSE(cached()) << "the mesh changed";
  write_ppm(100);
  EXPECT_FALSE(cached()) << "the texture changed";
  EXPECT_TRUE(cached()) << "nothing changed since";
}

// Every (sampler, spp) over K seeds: per-seed entries (distinct seeds, seed 0 the scene's), the
// mean RMSE with an interval around it, bias^2 + variance = MSE, the reference's variance, and
// one CSV row per seed.
TEST(CliCompare, SeedsWritePerSeedEntriesAndIntervals) {
  fs::path d = scratch_dir("compare_seeds");
  fs::path scene = write_scene(d, R"("width": 12, "height": 8)");
  auto [r, j] =
      run_compare(d, scene, "--samplers random,jitter --spp 2,4 --seeds 2 --reference-spp 64 --no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(j["seeds"].size(), 2u);
  EXPECT_NE(j["seeds"][0], j["seeds"][1]);
  EXPECT_GT(j["reference"]["variance"].get<double>(), 0);
  ASSERT_EQ(j["runs"].size(), 4u);
  for (const auto& run : j["runs"]) {
    ASSERT_EQ(run["per_seed"].size(), 2u) << run.dump();
    EXPECT_EQ(run["per_seed"][0]["seed"], j["seeds"][0]);
    EXPECT_EQ(run["per_seed"][1]["seed"], j["seeds"][1]);
    EXPECT_EQ(run["samples"].get<int64_t>(), 12 * 8 * run["spp"].get<int64_t>()) << "traced samples";
    EXPECT_NE(run["per_seed"][0]["rmse"], run["per_seed"][1]["rmse"]) << "independent seeds";
    const double m = run["rmse"], ci = run["rmse_ci95"];
    EXPECT_GT(ci, 0);
    EXPECT_DOUBLE_EQ(run["rmse_low"].get<double>(), m - ci);
    EXPECT_DOUBLE_EQ(run["rmse_high"].get<double>(), m + ci);
    EXPECT_NEAR(run["bias2"].get<double>() + run["variance"].get<double>(), run["mse"].get<double>(), 1e-9);
    EXPECT_GT(run["variance"].get<double>(), 0);
    EXPECT_GE(run["cpu_seconds"].get<double>(), 0);
  }
  std::stringstream csv;
  csv << std::ifstream(d / "report" / "results.csv").rdbuf();
  EXPECT_EQ(pdrt::test::line_count(csv.str()), 1 + 4 * 2) << "a header and one row per seed";
  EXPECT_NE(csv.str().find("seed_index,seed,"), std::string::npos);
}

// Issue 29: with one seed the console gives no interval and no bias/variance split (it printed
// "+- 0.00000 (95%, 1 seeds) ... variance 0"); with two it gives both.
TEST(CliCompare, OneSeedPrintsNoIntervalOnTheConsole) {
  fs::path d = scratch_dir("compare_one_seed");
  fs::path scene = write_scene(d, R"("width": 12, "height": 8)");
  for (int seeds : {1, 2}) {
    const auto r =
        run_compare(d, scene,
                    "--samplers random --spp 2 --seeds " + std::to_string(seeds) + " --reference-spp 16 --no-plots",
                    "r" + std::to_string(seeds))
            .cli;
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const bool one = seeds == 1;
    EXPECT_EQ(r.err.find("+-") == std::string::npos, one) << r.err;
    EXPECT_EQ(r.err.find("bias^2") == std::string::npos, one) << r.err;
    EXPECT_EQ(r.err.find("nan"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("1 seed: intervals, bias and variance need >= 2") != std::string::npos, one) << r.err;
  }
}

// Issue 28: the default sampler's seed-average on a render converges to the reference: over 64
// seeds, bias^2 within 1 % of the variance at 4, 16 and 64 spp (the measure the issue asks of
// any randomisation of the tables; its isometric shift, which keeps their distances, showed
// 1.0-1.5 % on comb and moving-square, docs/sampling.md). `regular`, the same samples in every
// seed, is the biased control the same check refuses.
TEST(CliCompare, PoissonSeedAverageOfARenderConvergesToTheReference) {
  fs::path d = scratch_dir("compare_poisson_bias");
  auto [r, j] = run_compare(d, fs::path(PDRT_SCENES_DIR) / "soft-shadows.json",
                            "--samplers poisson,regular --spp 4,16,64 --seeds 64 --reference-spp 1024 --width 40 "
                            "--height 30 --no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(j["runs"].size(), 6u);
  for (const auto& run : j["runs"]) {
    const double b2 = run["bias2"], var = run["variance"];
    if (run["sampler"] == "poisson")
      EXPECT_LT(std::abs(b2), 0.01 * var) << run["spp"] << " spp: bias^2 " << b2 << ", variance " << var;
    else
      EXPECT_GT(b2, 0.01 * var) << "regular at " << run["spp"] << " spp";
  }
}

// The samples-used analysis describes the runs' own samples: a screen-space sampler arranges
// a run's spp per pixel (here 16), not the scene file's (4), whose blocks would be other points.
TEST(CliCompare, SamplesUsedAreThoseOfTheRunsSampleCount) {
  fs::path d = scratch_dir("compare_used_shape");
  fs::path scene = write_scene(d);
  auto [r, j] =
      run_compare(d, scene, "--samplers zsobol,poisson-ss --spp 16 --seeds 1 --reference-spp 64 --no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const uint64_t seed = j["seeds"][0].get<uint64_t>();
  for (const auto& run : j["runs"]) {
    const std::string name = run["sampler"];
    auto rho = [&](int64_t shape_spp) {
      auto s = pdrt::make_sampler(name, seed, pdrt::SamplerShape{shape_spp, 24, 16});
      return pdrt::analyze_stream(*s, pdrt::Family::Lens, 24, 16, 16, 1024).rho_mean;
    };
    double reported = -1;
    for (const auto& u : run["used_samples"])
      if (u["family"] == "lens") reported = u["rho_mean"];
    EXPECT_DOUBLE_EQ(reported, rho(16)) << name;
    EXPECT_NE(rho(16), rho(4)) << name << ": the shapes give the same points, so the test cannot fail";
  }
}

// Issue 15: every run reports the sampler's share of its CPU time (profiler ticks) and the
// samples it used, per family: rho of each pixel's prefix and their periodogram.
TEST(CliCompare, ResultsReportTheSamplerShareAndTheSamplesUsed) {
  fs::path d = scratch_dir("compare_usage");
  fs::path scene = write_scene(d, R"("width": 24, "height": 16)");
  auto [r, j] =
      run_compare(d, scene, "--samplers random,poisson --spp 1,16 --seeds 1 --reference-spp 64 --no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* s : {"random", "poisson"}) EXPECT_TRUE(j["sampler_share"].contains(s)) << s;
  std::map<std::string, double> lens_rho;
  for (const auto& run : j["runs"]) {
    const auto& share = run["sampler_share"];
    ASSERT_GE(share["ticks"].get<int64_t>(), share["sampler_ticks"].get<int64_t>()) << run.dump();
    if (!share["share"].is_null()) {
      EXPECT_GE(share["share"].get<double>(), 0.0);
      EXPECT_LE(share["share"].get<double>(), 1.0);
    }
    ASSERT_EQ(run["used_samples"].size(), 5u);
    for (const auto& u : run["used_samples"]) {
      EXPECT_EQ(u["pixels"], 24 * 16);
      EXPECT_EQ(u["points"], run["spp"]);
      EXPECT_FALSE(u["spectrum"]["power"].empty());
      EXPECT_EQ(u["rho_mean"].is_null(), run["spp"] == 1) << u.dump();
      if (u["family"] == "lens" && run["spp"] == 16) lens_rho[run["sampler"]] = u["rho_mean"];
    }
  }
  EXPECT_GT(lens_rho["poisson"], 2 * lens_rho["random"]);
  std::stringstream csv;
  csv << std::ifstream(d / "report" / "results.csv").rdbuf();
  EXPECT_NE(csv.str().find("profile_ticks,sampler_ticks"), std::string::npos);
}

TEST(CliCompare, ResultsReportTheThreadsUsed) {
  fs::path d = scratch_dir("compare_threads");
  fs::path scene = write_scene(d);
  auto [r, j] = run_compare(d, scene, "--samplers random --spp 1 --reference-spp 4 --threads 1 --no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["threads"], 1);
}

// The report explains what it shows: heat maps with their colour bar per spp, the slope row's meaning.
TEST(CliCompare, ReportHasHeatMapFiguresAndExplainsTheSlope) {
  fs::path d = scratch_dir("compare_report");
  fs::path scene = write_scene(d);
  auto [r, j] = run_compare(d, scene, "--samplers random,jitter --spp 1,4 --reference-spp 16 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(j["heat_colormap"].size(), 5u);
  for (int n : {1, 4}) {
    EXPECT_GT(j["error_maps"]["scale"][std::to_string(n)].get<double>(), 0) << n;
    EXPECT_TRUE(fs::exists(d / "report" / "errors" / ("heat-" + std::to_string(n) + ".png"))) << n;
  }
  std::stringstream html;
  html << std::ifstream(d / "report" / "index.html").rdbuf();
  EXPECT_NE(html.str().find("-0.5 is plain Monte Carlo"), std::string::npos);
  EXPECT_NE(html.str().find("share one colour scale"), std::string::npos);
  EXPECT_NE(html.str().find("The sampler's share of render time"), std::string::npos);
  EXPECT_NE(html.str().find("The samples the renders used"), std::string::npos);
  EXPECT_TRUE(fs::exists(d / "report" / "used_spectra.png"));
}

TEST(CliCompare, AdaptiveSweepWritesCsvAndTargetRatio) {
  fs::path d = scratch_dir("compare_adaptive");
  fs::path scene = write_scene(d, R"("width": 16, "height": 12)");
  auto [r, j] = run_compare(d, scene,
                            "--samplers poisson --spp 2,8,32 --reference-spp 256 --adaptive --adaptive-target-spp 8 "
                            "--no-plots --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_GE(j["adaptive_sweep"].size(), 9u) << "threshold x 2^k, k = -4..4 (more while the target is not crossed)";
  ASSERT_LE(j["adaptive_sweep"].size(), 13u);
  EXPECT_DOUBLE_EQ(j["adaptive_sweep"][4]["threshold"].get<double>(), 1.0 / 16) << "the metric's default in the middle";
  EXPECT_EQ(j["adaptive_target"]["spp"], 8);
  const auto& t = j["adaptive_target"]["samplers"]["poisson"];
  ASSERT_TRUE(t["ratio"].is_number()) << t.dump();
  EXPECT_GT(t["ratio"].get<double>(), 0);
  std::stringstream csv;
  csv << std::ifstream(d / "report" / "adaptive.csv").rdbuf();
  EXPECT_EQ(pdrt::test::line_count(csv.str()), int(j["adaptive_sweep"].size()) + 1) << "a header and one row per run";
}

// Every sampler `compare` accepts has a colour of its own in the report's plots
// (plot_compare.py's COLORS): a missing one falls back to matplotlib's first, jitter's blue.
TEST(CliCompare, PlotsGiveEverySamplerItsOwnColour) {
  std::ifstream in(fs::path(PDRT_SCENES_DIR).parent_path() / "renderer" / "compare" / "plot_compare.py");
  std::stringstream script;
  script << in.rdbuf();
  std::smatch line;
  const std::string text = script.str();
  ASSERT_TRUE(std::regex_search(text, line, std::regex("COLORS = \\{([^}]*)\\}")));
  std::map<std::string, std::string> colours;
  const std::string entries = line[1];
  const std::regex entry("\"([^\"]+)\": \"(#[0-9a-fA-F]{6})\"");
  for (auto it = std::sregex_iterator(entries.begin(), entries.end(), entry); it != std::sregex_iterator(); ++it)
    colours[(*it)[1]] = (*it)[2];
  std::set<std::string> used;
  for (const std::string& name : pdrt::all_sampler_names()) {
    ASSERT_TRUE(colours.count(name)) << name << " has no colour in plot_compare.py";
    EXPECT_TRUE(used.insert(colours[name]).second) << name << " shares " << colours[name];
  }
}

TEST(CliCompare, BadOptionsAreUsageErrors) {
  fs::path d = scratch_dir("compare_bad");
  fs::path scene = write_scene(d);
  for (std::string a :
       {"--samplers foo", "--spp 4,2", "--spp 0", "--spp 64 --reference-spp 100", "--adaptive-metric foo",
        "--adaptive-variance foo", "--adaptive-decision foo", "--adaptive --adaptive-target-spp 3",
        "--reconstruction weights", "--seeds 0", "--seeds -1", "--seeds two", "--seeds 1.5",
        "--reconstruction rank --adaptive --adaptive-decision split",
        "--samplers poisson,poisson-ss --spp 1,4096 --reference-spp 16384 --width 2048 --height 2048"}) {
    auto r = run_pdrt("compare " + scene.string() + " --out " + (d / "r").string() + " --no-plots " + a);
    EXPECT_EQ(r.exit_code, 2) << a << ": " << r.err;
    EXPECT_EQ(pdrt::test::line_count(r.err), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(d / "r" / "results.json"));
}

// Ctrl-C: the render stops, the image so far is written and marked partial, exit 130. The
// signal goes once pdrt shows its progress line on a terminal, i.e. once a tile is done,
// however loaded the machine (a fixed delay or a CPU-time budget could find it still starting
// up, or done).
TEST(CliRender, InterruptWritesPartialImage) {
  fs::path d = scratch_dir("render_int");
  fs::path scene = write_scene(d, R"("width": 512, "height": 512)");
  fs::path out = d / "out.exr";
  pdrt::test::TerminalChild child("exec '" + std::string(PDRT_BINARY) + "' render " + scene.string() + " -o " +
                                  out.string() + " --spp 4096 --allow-long-render");
  ASSERT_GT(child.pid(), 0) << "no pseudo-terminal";
  const bool rendering = child.read_until("\033[Krender", 300);
  ::kill(child.pid(), rendering ? SIGINT : SIGKILL);
  const int status = child.finish(300);
  ASSERT_TRUE(rendering) << "pdrt never showed its progress: " << child.text();
  ASSERT_TRUE(WIFEXITED(status)) << child.text();
  EXPECT_EQ(WEXITSTATUS(status), 130) << child.text();
  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in) << "the partial image must be written";
  EXPECT_EQ(in->spec().get_string_attribute("pdrt:partial"), "true");
  // The summary counts the pixels that got samples, not a mean spp (issue 29).
  EXPECT_TRUE(std::regex_search(child.text(),
                                std::regex("wrote the partial image .*out\\.exr: [0-9]+ of 262144 pixels rendered "
                                           "at [0-9]+(–[0-9]+)? spp \\(of 4096\\)")))
      << child.text();
}

// --time-limit: the render stops when it is reached and writes what it has, marked partial with
// the spp every pixel reached, in the image, the stats and the summary; it asked for that, so it
// exits 0. A limit of a microsecond is reached before any pass (the scene build alone is longer).
namespace {
// Renders the 24 x 16 test scene into `d` (out.exr, stats.json) with `args`.
pdrt::test::CliResult render_with_stats(const fs::path& d, const std::string& args) {
  fs::path scene = write_scene(d, R"("width": 24, "height": 16)");
  return run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() + " --stats " +
                  (d / "stats.json").string() + " " + args);
}
}  // namespace

// The limit has passed before the first pass, so the image holds the time estimate's
// calibration alone (render_estimate.h): the first pass, 8 spp, of the pixels it took, here
// every pixel of a 24 x 16 film (24 blocks of 4 x 4, far fewer than its 0.05 s allow).
TEST(CliRender, TimeLimitWritesTheImageMarkedPartialWithItsSpp) {
  fs::path d = scratch_dir("render_time_limit");
  auto r = render_with_stats(d, "--spp 4096 --time-limit 0.000001");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto in = OIIO::ImageInput::open((d / "out.exr").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().get_string_attribute("pdrt:partial"), "true");
  EXPECT_EQ(in->spec().get_string_attribute("pdrt:spp_complete"), "8");
  nlohmann::json j = nlohmann::json::parse(std::ifstream(d / "stats.json"));
  EXPECT_EQ(j["partial"], true);
  EXPECT_EQ(j["spp_complete"], 8);
  EXPECT_NE(r.err.find("partial: every pixel at 8 spp or more"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stopped at the time limit of 1e-06 s"), std::string::npos) << r.err;
}

// A complete render says so everywhere: not partial, every pixel at the spp asked for.
TEST(CliRender, CompleteRenderIsMarkedCompleteWithItsSpp) {
  fs::path d = scratch_dir("render_complete");
  auto r = render_with_stats(d, "--spp 12 --time-limit 3600 -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(std::ifstream(d / "stats.json"));
  EXPECT_EQ(j["partial"], false);
  EXPECT_EQ(j["spp_complete"], 12);
  EXPECT_GT(j["estimate"]["seconds"].get<double>(), 0);
  EXPECT_GT(j["estimate"]["calibration_samples"].get<int64_t>(), 0);
}

// film.crop_window: the image written has the crop's size (pbrt-v4's ceil rule: 24 x 16 film,
// [0.25, 0.75] x [0.5, 1] is pixels 6..17 x 8..15), the stats name those pixels, and
// --width/--height apply the same window to the new size; a window the new size leaves
// without a pixel is an input error, not a crash.
TEST(CliRender, CropWindowWritesTheCroppedImageAndNamesItsPixels) {
  fs::path d = scratch_dir("render_crop");
  fs::path scene = write_scene(d, R"("width": 24, "height": 16, "crop_window": [0.25, 0.75, 0.5, 1])");
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() + " --stats " +
                    (d / "stats.json").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto in = OIIO::ImageInput::open((d / "out.exr").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 12);
  EXPECT_EQ(in->spec().height, 8);
  nlohmann::json j = nlohmann::json::parse(std::ifstream(d / "stats.json"));
  EXPECT_EQ(j["crop_pixels"], nlohmann::json::array({6, 18, 8, 16}));
  EXPECT_EQ(j["width"], 24);
  EXPECT_DOUBLE_EQ(j["spp_mean"].get<double>(), 4);
  r = run_pdrt("render " + scene.string() + " -o " + (d / "small.exr").string() + " --width 48 --height 32 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  in = OIIO::ImageInput::open((d / "small.exr").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 24);
  EXPECT_EQ(in->spec().height, 16);
  fs::path thin = write_scene(d, R"("width": 24, "height": 16, "crop_window": [0.25, 0.26, 0, 1])");
  r = run_pdrt("render " + thin.string() + " -o " + (d / "thin.exr").string() + " --width 2 --quiet");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("film.crop_window covers no pixel of the 2x16 film"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "thin.exr"));
}

// The biased path regularisation is named wherever the image goes: the stats, the EXR's
// metadata and the summary line.
TEST(CliRender, RegularizeIsNamedInTheStatsMetadataAndSummary) {
  fs::path d = scratch_dir("render_regularize");
  fs::path scene = write_scene(d);
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() + " --spp 1 --regularize --stats " +
                    (d / "stats.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(std::ifstream(d / "stats.json"))["regularize"].get<bool>());
  auto in = OIIO::ImageInput::open((d / "out.exr").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().get_string_attribute("pdrt:regularize"), "true");
  EXPECT_NE(r.err.find("regularized (biased)"), std::string::npos) << r.err;
}

TEST(CliRender, StatsSayRegularizeIsOffByDefault) {
  fs::path d = scratch_dir("render_no_regularize");
  fs::path scene = write_scene(d);
  auto r = run_pdrt("render " + scene.string() + " -o " + (d / "out.exr").string() + " --spp 1 --quiet --stats " +
                    (d / "stats.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(nlohmann::json::parse(std::ifstream(d / "stats.json"))["regularize"].get<bool>());
}

// compare renders unbiased unless asked: a scene's integrator.regularize is ignored (and said
// so), --regularize turns it on and the report names it.
TEST(CliCompare, RendersUnregularizedUnlessAskedAndNamesIt) {
  fs::path d = scratch_dir("compare_regularize");
  fs::path scene = d / "scene.json";
  {
    std::string text;
    std::ifstream in(write_scene(d));
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    text.insert(text.find("\"materials\""), "\"integrator\": {\"regularize\": true},\n  ");
    std::ofstream(scene) << text;
  }
  const std::string common = "--samplers random --spp 1 --seeds 1 --reference-spp 4 --width 8 --height 8 --no-plots";
  const CompareRun plain = run_compare(d, scene, common, "plain");
  ASSERT_EQ(plain.cli.exit_code, 0) << plain.cli.err;
  EXPECT_NE(plain.cli.err.find("sets integrator.regularize"), std::string::npos) << plain.cli.err;
  EXPECT_FALSE(plain.results["regularize"].get<bool>());
  const CompareRun reg = run_compare(d, scene, common + " --regularize", "reg");
  ASSERT_EQ(reg.cli.exit_code, 0) << reg.cli.err;
  EXPECT_TRUE(reg.results["regularize"].get<bool>());
}
