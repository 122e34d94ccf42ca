// The render settings' vocabularies (scene/settings_names.h, the samplers' in
// sampling/samplers/sampler.h) and the validator of settings taken together
// (scene/render_settings.h): every value round-trips through its one name table, and a broken
// rule is refused with the same words from a JSON scene, a pbrt scene and a render.
#include "renderer/render/renderer.h"
#include "renderer/scene/render_settings.h"
#include "renderer/scene/scene_loader.h"
#include "sampling/core/errors.h"
#include "sampling/samplers/sampler.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace pdrt;

namespace {

template <class E, std::size_t N>
void expect_round_trip(const NamedValue<E> (&table)[N]) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < N; ++i) {
    const E v = E(i);
    const std::string name = name_in(table, v);
    EXPECT_NE(name, "?") << i;
    EXPECT_TRUE(seen.insert(name).second) << name << " twice";
    E back{};
    ASSERT_TRUE(parse_name_in(table, name, &back)) << name;
    EXPECT_EQ(back, v) << name;
    EXPECT_EQ(value_named(table, name), v) << name;
  }
  E untouched = E(N - 1);
  EXPECT_FALSE(parse_name_in(table, "no-such-name", &untouched));
  EXPECT_EQ(untouched, E(N - 1));
  EXPECT_THROW(value_named(table, ""), std::invalid_argument);
}

fs::path temp_file(const std::string& name, const std::string& text) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir =
      fs::temp_directory_path() / ("pdrt_settings_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

const std::string kSplitRefusal =
    "adaptive decision \"split\" needs reconstruction \"importance\" or \"splat\", not \"rank\"";

}  // namespace

TEST(SettingsNames, EveryValueRoundTripsThroughItsTable) {
  expect_round_trip(kSamplerNames);
  expect_round_trip(kReconstructionNames);
  expect_round_trip(kAdaptiveMetricNames);
  expect_round_trip(kAdaptiveVarianceNames);
  expect_round_trip(kAdaptiveDecisionNames);
  expect_round_trip(kEnvironmentSamplingNames);
}

TEST(SettingsNames, ListsAndSamplersComeFromTheTables) {
  EXPECT_EQ(name_list(kReconstructionNames), "importance, splat, rank");
  EXPECT_EQ(name_list(kAdaptiveDecisionNames, " | "), "shared | split");
  EXPECT_EQ(sampler_name_list(), name_list(kSamplerNames));
  EXPECT_EQ(all_sampler_names(), names_in(kSamplerNames));
  // The Monte Carlo samplers that render under every setting: every one but regular and
  // poisson-ip (splatting only), in table order.
  std::vector<std::string> mc = names_in(kSamplerNames);
  mc.erase(std::find(mc.begin(), mc.end(), sampler_name(SamplerKind::Regular)));
  mc.erase(std::find(mc.begin(), mc.end(), sampler_name(SamplerKind::PoissonIP)));
  EXPECT_EQ(sampler_names(), mc);
  // Each sampler calls itself by its table name.
  for (const NamedValue<SamplerKind>& s : kSamplerNames) EXPECT_EQ(make_sampler(s.value, 1)->name(), s.name);
}

TEST(RenderSettings, KeptRulesGiveNoProblem) {
  SceneDesc s;
  EXPECT_FALSE(render_settings_problem(s));
  s.sampler.adaptive.enabled = true;
  s.sampler.adaptive.decision = AdaptiveDecision::Split;
  EXPECT_FALSE(render_settings_problem(s)) << "split with importance";
  s.sampler.adaptive.enabled = false;
  s.film.filter.reconstruction = Reconstruction::Rank;
  EXPECT_FALSE(render_settings_problem(s)) << "split only matters with adaptive on";
  s.sampler.adaptive.min_spp = 64, s.sampler.adaptive.max_spp = 8;
  EXPECT_FALSE(render_settings_problem(s)) << "the spp range only matters with adaptive on";
}

TEST(RenderSettings, EachRuleNamesItsSetting) {
  SceneDesc s;
  s.sampler.adaptive.enabled = true;
  s.sampler.adaptive.decision = AdaptiveDecision::Split;
  s.film.filter.reconstruction = Reconstruction::Rank;
  auto p = render_settings_problem(s);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->setting, SettingsProblem::Setting::AdaptiveDecision);
  EXPECT_EQ(p->message, kSplitRefusal);
  s.sampler.adaptive.min_spp = 64, s.sampler.adaptive.max_spp = 8;
  p = render_settings_problem(s);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->setting, SettingsProblem::Setting::AdaptiveSpp);
  EXPECT_EQ(p->message, "adaptive: min_spp (64) must be <= max_spp (8)");
  SceneDesc c;
  c.film.width = 8, c.film.height = 8, c.film.crop_window = {0.51f, 0.6f, 0, 1};
  p = render_settings_problem(c);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->setting, SettingsProblem::Setting::CropWindow);
  EXPECT_EQ(p->message,
            "film.crop_window covers no pixel of the 8x8 film (pixels ceil(size * bound) are [5, 5) x [0, 8))");
}

// The same refusal, in the same words, from a JSON scene file, from the renderer (a pbrt scene
// cannot ask for adaptive refinement: the command line's overrides are tested in
// tests/app/test_cli_render.cpp).
TEST(RenderSettings, SplitWithRankIsRefusedAlikeByTheLoaderAndTheRenderer) {
  const fs::path json = temp_file("s.json", R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 8, "height": 8, "filter": {"reconstruction": "rank"}},
  "sampler": {"adaptive": {"decision": "split"}}
})");
  const std::string from_file = input_error([&] { load_scene(json); });
  EXPECT_NE(from_file.find(":4:40: sampler.adaptive.decision \"split\" needs reconstruction \"importance\" or "
                           "\"splat\", not \"rank\""),
            std::string::npos)
      << from_file;
  SceneDesc s = test::base_scene(8, 8, 4);
  s.sampler.adaptive.enabled = true;
  s.sampler.adaptive.decision = AdaptiveDecision::Split;
  s.film.filter.reconstruction = Reconstruction::Rank;
  auto sampler = make_scene_sampler(s.sampler, s.film);
  EXPECT_EQ(input_error([&] { render(s, *sampler, RenderOptions{}); }), kSplitRefusal);
}

TEST(RenderSettings, EmptyCropIsRefusedAlikeByBothLoadersAndTheRenderer) {
  const std::string words = "covers no pixel of the 8x8 film (pixels ceil(size * bound) are [5, 5) x [0, 8))";
  const fs::path json = temp_file("s.json", R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 8, "height": 8, "crop_window": [0.51, 0.6, 0, 1]}
})");
  EXPECT_NE(input_error([&] { load_scene(json); }).find("film.crop_window " + words), std::string::npos);
  const fs::path pbrt = temp_file("s.pbrt",
                                  "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\n"
                                  "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8 "
                                  "\"float cropwindow\" [0.51 0.6 0 1]\nWorldBegin\n");
  EXPECT_NE(input_error([&] { load_scene(pbrt); }).find("\"float cropwindow\" " + words), std::string::npos);
  SceneDesc s = test::base_scene(8, 8, 4);
  s.film.crop_window = {0.51f, 0.6f, 0, 1};
  auto sampler = make_scene_sampler(s.sampler, s.film);
  EXPECT_EQ(input_error([&] { render(s, *sampler, RenderOptions{}); }),
            s.film.size_where + ": film.crop_window " + words);
}

// The samplers that order pixels (zsobol, poisson-ss) refuse a film and first pass whose Morton
// and sample index need more than 32 bits, located at the film's size in a scene file; the
// first pass is adaptive min_spp when refining.
TEST(RenderSettings, PixelOrderPastThirtyTwoBitsIsRefusedAtTheFilmSize) {
  const fs::path json = temp_file("s.json", R"({
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "film": {"width": 4096, "height": 300},
  "sampler": {"type": "poisson-ss", "spp": 1024}
})");
  EXPECT_NE(
      input_error([&] { load_scene(json); })
          .find(":3:21: film.width/height: sampler \"poisson-ss\" orders 4096x300 pixels at 1024 spp with 34 bits "
                "of Morton and sample index, at most 32 (fewer samples per pixel or a smaller image)"),
      std::string::npos);
  SceneDesc s;
  s.film.width = 4096, s.film.height = 300, s.sampler.spp = 1024;
  for (const char* name : {"zsobol", "poisson-ss"}) {
    s.sampler.type = name;
    auto p = render_settings_problem(s);
    ASSERT_TRUE(p) << name;
    EXPECT_EQ(p->setting, SettingsProblem::Setting::PixelOrder);
  }
  s.sampler.spp = 256;
  EXPECT_FALSE(render_settings_problem(s)) << "32 bits fit";
  s.sampler.spp = 1024, s.sampler.adaptive.enabled = true, s.sampler.adaptive.min_spp = 256;
  EXPECT_FALSE(render_settings_problem(s)) << "the first pass is min_spp";
  s.sampler.type = "poisson", s.sampler.adaptive.enabled = false;
  EXPECT_FALSE(render_settings_problem(s)) << "per-pixel samplers order nothing";
}
