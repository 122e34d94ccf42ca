// The pbrt-v4 corpus (tests/data/pbrt/): one small file per directive and parameter type, each
// beside NAME.expected.json, the part of the imported scene that file is about (as `pdrt
// convert --inline-meshes` writes it) and the exact report; and malformed files under errors/
// whose first line is `# error: MESSAGE` with file:line:col; and scenes under equivalence/
// written twice, as .pbrt and as pdrt JSON, that must render the same image. Paths in
// messages are relative to the corpus folder.
#include "renderer/scene/pbrt/pbrt_scene_builder.h"
#include "renderer/scene/scene_loader.h"
#include "renderer/scene/scene_writer.h"
#include "sampling/core/errors.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace pdrt;

namespace {

const fs::path kCorpus = fs::path(PDRT_TEST_DATA_DIR) / "pbrt";

std::string read(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> files(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".pbrt") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// Messages name files by the path they were opened with: drop the corpus folder.
std::string relative(std::string s) {
  const std::string prefix = kCorpus.string() + "/";
  for (size_t at; (at = s.find(prefix)) != std::string::npos;) s.erase(at, prefix.size());
  return s;
}

// `expected` is a subset of `actual`: every key it has, with equal values; numbers to a
// relative 1e-5 (floats written as doubles); {"$length": n} matches any array of n values.
void match(const json& expected, const json& actual, const std::string& where, std::vector<std::string>* errors) {
  if (expected.is_object() && expected.contains("$length")) {
    if (!actual.is_array() || actual.size() != expected["$length"].get<size_t>())
      errors->push_back(where + ": expected an array of " + expected["$length"].dump() + " values, got " +
                        actual.dump().substr(0, 80));
    return;
  }
  if (expected.is_number() && actual.is_number()) {
    const double e = expected.get<double>(), a = actual.get<double>();
    if (!(std::abs(e - a) <= 1e-5 * std::max(1.0, std::abs(e))))
      errors->push_back(where + ": expected " + expected.dump() + ", got " + actual.dump());
    return;
  }
  if (expected.type() != actual.type()) {
    errors->push_back(where + ": expected " + expected.dump().substr(0, 80) + ", got " + actual.dump().substr(0, 80));
    return;
  }
  if (expected.is_object()) {
    for (const auto& [k, v] : expected.items()) {
      if (!actual.contains(k))
        errors->push_back(where + "." + k + ": missing");
      else
        match(v, actual[k], where + "." + k, errors);
    }
  } else if (expected.is_array()) {
    if (expected.size() != actual.size()) {
      errors->push_back(where + ": expected " + std::to_string(expected.size()) + " entries, got " +
                        std::to_string(actual.size()));
      return;
    }
    for (size_t i = 0; i < expected.size(); ++i)
      match(expected[i], actual[i], where + "[" + std::to_string(i) + "]", errors);
  } else if (expected != actual) {
    errors->push_back(where + ": expected " + expected.dump() + ", got " + actual.dump());
  }
}

// The imported scene as convert writes it, plus the environment map's size and mean texel
// (its texels are written to an EXR the JSON only names).
json imported(const fs::path& file, std::vector<std::string>* report) {
  PbrtImport im = load_pbrt_scene(file, false);
  for (const std::string& line : im.report) report->push_back(relative(line));
  const fs::path dir = fs::temp_directory_path() / ("pdrt_corpus_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path out = dir / (file.stem().string() + ".json");
  write_scene_json(im.scene, out, {.inline_meshes = true});
  json j = json::parse(read(out));
  fs::remove_all(dir);
  // Files convert names by absolute path: relative to the corpus, as the expectations write them.
  auto strip = [](auto& self, json& v) -> void {
    if (v.is_string()) v = relative(v.get<std::string>());
    if (v.is_structured())
      for (auto& child : v) self(self, child);
  };
  strip(strip, j);
  const EnvironmentDesc& e = im.scene.environment;
  if (e.has_map()) {
    double mean[3] = {0, 0, 0};
    for (size_t i = 0; i < e.rgb.size(); ++i) mean[i % 3] += e.rgb[i] / double(e.width * e.height);
    j["$environment"] = {{"width", e.width}, {"height", e.height}, {"mean", {mean[0], mean[1], mean[2]}}};
  }
  return j;
}

}  // namespace

TEST(PbrtCorpus, EveryFileImportsToItsExpectedSceneAndReport) {
  const std::vector<fs::path> all = files(kCorpus);
  ASSERT_GE(all.size(), 40u);
  for (const fs::path& f : all) {
    SCOPED_TRACE(f.filename().string());
    const fs::path expect_file = fs::path(f).replace_extension(".expected.json");
    ASSERT_TRUE(fs::exists(expect_file)) << expect_file;
    const json expect = json::parse(read(expect_file));
    std::vector<std::string> report;
    json actual;
    try {
      actual = imported(f, &report);
    } catch (const InputError& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    std::vector<std::string> errors;
    match(expect.at("scene"), actual, "scene", &errors);
    for (const std::string& e : errors) ADD_FAILURE() << e;
    EXPECT_EQ(report, expect.value("report", std::vector<std::string>{}));
  }
}

TEST(PbrtCorpus, EveryMalformedFileIsRefusedWithItsPosition) {
  const std::vector<fs::path> all = files(kCorpus / "errors");
  ASSERT_GE(all.size(), 15u);
  for (const fs::path& f : all) {
    SCOPED_TRACE(f.filename().string());
    const std::string text = read(f);
    ASSERT_EQ(text.rfind("# error: ", 0), 0u) << "the first line must be # error: MESSAGE";
    const std::string expect = text.substr(9, text.find('\n') - 9);
    try {
      load_pbrt_scene(f, false);
      ADD_FAILURE() << "no error; expected " << expect;
    } catch (const InputError& e) {
      EXPECT_EQ(relative(e.what()), expect);
    }
  }
}

TEST(PbrtCorpus, CoversEveryDirectiveAndParameterType) {
  std::string text;
  for (const fs::path& f : files(kCorpus)) text += read(f);
  for (const fs::path& f : files(kCorpus / "errors")) text += read(f);
  for (const char* d : {"Identity",
                        "Translate",
                        "Scale",
                        "Rotate",
                        "LookAt",
                        "CoordinateSystem",
                        "CoordSysTransform",
                        "Transform",
                        "ConcatTransform",
                        "TransformBegin",
                        "TransformEnd",
                        "ReverseOrientation",
                        "ActiveTransform",
                        "TransformTimes",
                        "Camera",
                        "Film",
                        "PixelFilter",
                        "Sampler",
                        "Integrator",
                        "ColorSpace",
                        "Option",
                        "Accelerator",
                        "WorldBegin",
                        "AttributeBegin",
                        "AttributeEnd",
                        "Attribute",
                        "Material",
                        "MakeNamedMaterial",
                        "NamedMaterial",
                        "Texture",
                        "AreaLightSource",
                        "LightSource",
                        "Shape",
                        "ObjectBegin",
                        "ObjectEnd",
                        "ObjectInstance",
                        "MakeNamedMedium",
                        "MediumInterface",
                        "Include",
                        "Import"})
    EXPECT_TRUE(std::regex_search(text, std::regex(std::string("(^|\n)\\s*") + d + "\\b"))) << "no file uses " << d;
  for (const char* t : {"integer", "float", "point2", "vector2", "point3", "vector3", "normal3", "normal", "point",
                        "vector", "bool", "string", "texture", "rgb", "color", "spectrum", "blackbody"})
    EXPECT_NE(text.find(std::string("\"") + t + " "), std::string::npos) << "no parameter of type " << t;
}

TEST(PbrtCorpus, EquivalentScenesRenderTheImageOfTheirJsonTwin) {
  // Same sampler, seed and description: the same image up to the last bits of transforms and
  // directions that pbrt's parameters reach through other arithmetic (normalised in double,
  // matrices built from sin and cos).
  const std::vector<fs::path> all = files(kCorpus / "equivalence");
  ASSERT_GE(all.size(), 3u);
  for (const fs::path& f : all) {
    SCOPED_TRACE(f.filename().string());
    // pbrt-v4 differs from both twins only where pdrt renders in RGB and emitters only emit:
    // nothing else may be reported.
    const PbrtImport im = load_pbrt_scene(f, false);
    for (const std::string& line : im.report)
      EXPECT_TRUE(line.find("per wavelength") != std::string::npos || line.find("only emits") != std::string::npos)
          << line;
    SceneDesc p = im.scene;
    p.file = f;
    const SceneDesc j = load_scene(fs::path(f).replace_extension(".json"));
    const Image a = test::render_quietly(p).image, b = test::render_quietly(j).image;
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    double diff = 0, sum = 0;
    int differ = 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        const double d = std::abs(test::mean_rgb(a, x, y) - test::mean_rgb(b, x, y));
        diff += d, sum += test::mean_rgb(b, x, y);
        differ += d > 1e-4 * std::max(1.0, test::mean_rgb(b, x, y));
      }
    EXPECT_GT(sum, 0.05 * a.width * a.height);  // lit, not black
    EXPECT_LE(diff, 1e-5 * sum) << "sum " << sum;
    EXPECT_LE(differ, 1) << "pixels that differ by more than 1e-4";
  }
}
