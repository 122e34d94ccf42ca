// The pbrt-v4 scene-file grammar (issue 18): tokens with their file:line:col, directives and
// their arguments, typed parameter lists, Include/Import, and every malformed input refused with
// a one-line message that names where it is.
#include "renderer/scene/pbrt/pbrt_parser.h"
#include "sampling/core/errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace pdrt;
namespace fs = std::filesystem;

namespace {

std::vector<PbrtDirective> parse(const std::string& text) { return parse_pbrt_text(text, "s.pbrt", "."); }

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "messages are one line: " << m;
    return m;
  }
  ADD_FAILURE() << "expected an InputError for: " << text;
  return "";
}

fs::path temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path dir =
      fs::temp_directory_path() / ("pdrt_pbrt_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

}  // namespace

TEST(PbrtTokenizer, SplitsWordsStringsAndBracketsAndSkipsComments) {
  std::string text = "Shape \"sphere\"# a comment \"not a string\"\n  [1 -2.5e1]\"a\\\"b\\n\"";
  PbrtTokenizer tok(text, std::make_shared<const std::string>("t.pbrt"));
  std::vector<PbrtToken> ts;
  for (PbrtToken t = tok.next(); t.kind != PbrtToken::Kind::End; t = tok.next()) ts.push_back(t);
  ASSERT_EQ(ts.size(), 7u);
  EXPECT_EQ(ts[0].text, "Shape");
  EXPECT_EQ(ts[1].kind, PbrtToken::Kind::String);
  EXPECT_EQ(ts[1].text, "sphere");
  EXPECT_EQ(ts[2].kind, PbrtToken::Kind::Open);
  EXPECT_EQ(ts[2].at.str(), "t.pbrt:2:3");
  EXPECT_EQ(ts[3].text, "1");
  EXPECT_EQ(ts[4].text, "-2.5e1");
  EXPECT_EQ(ts[4].at.str(), "t.pbrt:2:6");
  EXPECT_EQ(ts[5].kind, PbrtToken::Kind::Close);
  EXPECT_EQ(ts[6].text, "a\"b\n");
}

TEST(PbrtParser, TypesEveryDirectiveByItsName) {
  using K = PbrtDirectiveKind;
  const std::vector<std::pair<std::string, K>> expected = {
      {"Identity", K::Identity},
      {"Translate 1 2 3", K::Translate},
      {"Scale 1 2 3", K::Scale},
      {"Rotate 90 0 0 1", K::Rotate},
      {"LookAt 0 0 0 0 0 1 0 1 0", K::LookAt},
      {"Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]", K::Transform},
      {"ConcatTransform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]", K::ConcatTransform},
      {"CoordinateSystem \"c\"", K::CoordinateSystem},
      {"CoordSysTransform \"c\"", K::CoordSysTransform},
      {"ActiveTransform All", K::ActiveTransform},
      {"TransformTimes 0 1", K::TransformTimes},
      {"ReverseOrientation", K::ReverseOrientation},
      {"WorldBegin", K::WorldBegin},
      {"WorldEnd", K::WorldEnd},
      {"AttributeBegin", K::AttributeBegin},
      {"AttributeEnd", K::AttributeEnd},
      {"TransformBegin", K::TransformBegin},
      {"TransformEnd", K::TransformEnd},
      {"Attribute \"shape\" \"float radius\" 2", K::Attribute},
      {"ObjectBegin \"o\"", K::ObjectBegin},
      {"ObjectEnd", K::ObjectEnd},
      {"ObjectInstance \"o\"", K::ObjectInstance},
      {"Camera \"perspective\"", K::Camera},
      {"Film \"rgb\"", K::Film},
      {"PixelFilter \"box\"", K::PixelFilter},
      {"Sampler \"halton\"", K::Sampler},
      {"Integrator \"path\"", K::Integrator},
      {"Accelerator \"bvh\"", K::Accelerator},
      {"ColorSpace \"srgb\"", K::ColorSpace},
      {"Option \"bool wavefront\" true", K::Option},
      {"Texture \"t\" \"float\" \"constant\"", K::Texture},
      {"Material \"diffuse\"", K::Material},
      {"MakeNamedMaterial \"m\" \"string type\" \"diffuse\"", K::MakeNamedMaterial},
      {"NamedMaterial \"m\"", K::NamedMaterial},
      {"LightSource \"point\"", K::LightSource},
      {"AreaLightSource \"diffuse\"", K::AreaLightSource},
      {"Shape \"sphere\"", K::Shape},
      {"MakeNamedMedium \"m\" \"string type\" \"homogeneous\"", K::MakeNamedMedium},
      {"MediumInterface \"m\"", K::MediumInterface},
  };
  std::string text;
  for (const auto& [line, kind] : expected) text += line + "\n";
  auto ds = parse(text);
  ASSERT_EQ(ds.size(), expected.size());
  for (size_t i = 0; i < ds.size(); ++i) {
    EXPECT_EQ(ds[i].kind, expected[i].second) << expected[i].first;
    EXPECT_EQ(ds[i].name, expected[i].first.substr(0, expected[i].first.find(' '))) << expected[i].first;
  }
}

TEST(PbrtParser, ReadsDirectiveArgumentsAndTypedParameters) {
  auto ds = parse(
      "LookAt 0 1 2  3 4 5  0 1 0\n"
      "Camera \"perspective\" \"float fov\" 45 \"float lensradius\" [0.1]\n"
      "Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]\n"
      "ConcatTransform 1 0 0 0 0 1 0 0 0 0 1 0 1 2 3 1\n"
      "ActiveTransform EndTime\n"
      "Texture \"checks\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [1 0 0] \"texture tex2\" \"other\"\n"
      "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2] \"bool x\" true \"bool y\" "
      "\"false\"\n"
      "MediumInterface \"a\" \"b\"\n"
      "Option \"bool disablepixeljitter\" true\n");
  ASSERT_EQ(ds.size(), 9u);
  EXPECT_EQ(ds[0].name, "LookAt");
  EXPECT_EQ(ds[0].numbers.size(), 9u);
  EXPECT_EQ(ds[1].strings, std::vector<std::string>{"perspective"});
  EXPECT_DOUBLE_EQ(ds[1].params.get_float("fov", 0), 45);
  EXPECT_DOUBLE_EQ(ds[1].params.get_float("lensradius", 0), 0.1);
  EXPECT_EQ(ds[2].numbers.size(), 16u);
  EXPECT_EQ(ds[3].numbers[13], 2);
  EXPECT_EQ(ds[4].strings[0], "EndTime");
  EXPECT_EQ(ds[5].strings, (std::vector<std::string>{"checks", "spectrum", "checkerboard"}));
  EXPECT_EQ(ds[5].params.find_texture("tex2").value(), "other");
  auto P = ds[6].params.point3s("P");
  ASSERT_EQ(P.size(), 3u);
  EXPECT_EQ(P[1].x, 1);
  EXPECT_EQ(ds[6].params.ints("indices"), (std::vector<int64_t>{0, 1, 2}));
  EXPECT_TRUE(ds[6].params.get_bool("x", false));
  EXPECT_FALSE(ds[6].params.get_bool("y", true));
  EXPECT_EQ(ds[7].strings.size(), 2u);
  EXPECT_EQ(ds[8].params.list.size(), 1u);
  EXPECT_EQ(ds[1].at.str(), "s.pbrt:2:1");
  EXPECT_EQ(ds[1].params.list[1].at.str(), "s.pbrt:2:37");
}

TEST(PbrtParser, ParameterLookupsCheckTheDeclaredTypeAndTrackUse) {
  auto ds = parse("Shape \"sphere\" \"float radius\" 2 \"point zmin\" [0 0 0] \"string unknown\" \"x\"");
  const PbrtParams& p = ds[0].params;
  EXPECT_DOUBLE_EQ(p.get_float("radius", 1), 2);
  try {
    p.find_float("zmin");
    ADD_FAILURE() << "a point3 read as float";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "s.pbrt:1:33: \"point zmin\" must be of type float, not point");
  }
  EXPECT_EQ(p.point3s("zmin").size(), 1u);
  auto unused = p.unused();
  ASSERT_EQ(unused.size(), 1u);
  EXPECT_EQ(unused[0]->name, "unknown");
}

TEST(PbrtParser, ExpandsIncludeAndImportRelativeToTheIncludingFile) {
  fs::path dir = temp_dir();
  fs::create_directories(dir / "sub");
  write(dir / "main.pbrt", "WorldBegin\nInclude \"sub/a.pbrt\"\nImport \"sub/b.pbrt\"\nAttributeEnd\n");
  write(dir / "sub/a.pbrt", "AttributeBegin\nInclude \"c.pbrt\"\n");  // c.pbrt beside a.pbrt
  write(dir / "sub/b.pbrt", "Shape \"sphere\"\n");
  write(dir / "sub/c.pbrt", "\n  Translate 1 2 3\n");
  auto ds = parse_pbrt_file(dir / "main.pbrt");
  std::vector<std::string> names;
  for (const auto& d : ds) names.push_back(d.name);
  EXPECT_EQ(names, (std::vector<std::string>{"WorldBegin", "AttributeBegin", "Translate", "Shape", "AttributeEnd"}));
  EXPECT_EQ(ds[2].at.str(), (dir / "sub/c.pbrt").string() + ":2:3");
  fs::remove_all(dir);
}

TEST(PbrtParser, RefusesIncludeCyclesAndMissingTargetsAtTheInclude) {
  fs::path dir = temp_dir();
  write(dir / "a.pbrt", "WorldBegin\n  Include \"b.pbrt\"\n");
  write(dir / "b.pbrt", "Include \"a.pbrt\"\n");
  write(dir / "c.pbrt", "Include \"missing.pbrt\"\n");
  try {
    parse_pbrt_file(dir / "a.pbrt");
    ADD_FAILURE() << "cycle accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "b.pbrt").string() + ":1:1: \"" + (dir / "a.pbrt").string() +
                                         "\" includes itself (an Include cycle)");
  }
  try {
    parse_pbrt_file(dir / "c.pbrt");
    ADD_FAILURE() << "missing include accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "c.pbrt").string() + ":1:1: cannot open \"" +
                                         (dir / "missing.pbrt").string() + "\": No such file or directory");
  }
  fs::remove_all(dir);
}

TEST(PbrtParser, RefusesMalformedFilesWithTheirPosition) {
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      {"Shape \"sphere\n", "s.pbrt:1:7: string is not closed on its line (missing '\"')"},
      {"Shape \"sphere\" \"float radius\" [1 2",
       "s.pbrt:1:31: '[' of \"radius\" is not closed (found the end of the file at s.pbrt:1:35)"},
      {"Shape \"sphere\" \"float radius\" [1 \"point p\" [0 0 0]",
       "s.pbrt:1:31: '[' of \"radius\" is not closed (found '[' at s.pbrt:1:44)"},
      {"Frobnicate 1", "s.pbrt:1:1: unknown directive \"Frobnicate\""},
      {"  \"sphere\"", "s.pbrt:1:3: expected a directive, got the string \"sphere\""},
      {"Translate 1 x 3", "s.pbrt:1:13: Translate argument 2 must be a number, got \"x\""},
      {"Translate 1 2", "s.pbrt:1:14: Translate argument 3 must be a number, got the end of the file"},
      {"Rotate 1e999 0 0 1", "s.pbrt:1:8: Rotate argument 1 1e999 is out of range"},
      {"Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0]", "s.pbrt:1:41: Transform needs 16 numbers, got 15"},
      {"ActiveTransform Sometimes", "s.pbrt:1:17: ActiveTransform takes StartTime, EndTime or All, got \"Sometimes\""},
      {"Shape sphere", "s.pbrt:1:7: Shape needs a quoted string, got \"sphere\""},
      {"Shape \"sphere\" \"float\" 1", "s.pbrt:1:16: a parameter is declared as \"type name\", got \"float\""},
      {"Shape \"sphere\" \"real radius\" 1", "s.pbrt:1:16: unknown parameter type \"real\" (of \"radius\")"},
      {"Shape \"sphere\" \"float radius\" \"one\"",
       "s.pbrt:1:31: a value of \"float radius\" must be a number, got the string \"one\""},
      {"Shape \"sphere\" \"float radius\" nan",
       "s.pbrt:1:31: a value of \"float radius\" must be a number, got \"nan\""},
      {"Shape \"sphere\" \"float radius\" []", "s.pbrt:1:16: \"float radius\" has no values"},
      {"Shape \"sphere\" \"bool x\" 1", "s.pbrt:1:25: a value of \"bool x\" must be true or false, got \"1\""},
      {"Shape \"sphere\" \"string x\" [a]", "s.pbrt:1:28: a value of \"string x\" must be a quoted string, got \"a\""},
      {"Shape \"sphere\" \"float r\" 1 \"float r\" 2",
       "s.pbrt:1:28: parameter \"r\" is given twice (first at s.pbrt:1:16)"},
      {"Shape \"sphere\" \"float r\" ]", "s.pbrt:1:26: \"float r\" needs a value, got ']'"},
      {"Shape \"a\\qb\"", "s.pbrt:1:9: unknown escape '\\q' in a string"},
      {"Shape \"sphere\" \x01", "s.pbrt:1:16: unexpected control character (byte 1)"},
      {"Option", "s.pbrt:1:1: Option needs a \"type name\" value"},
  };
  for (const Case& c : cases) EXPECT_EQ(error_of(c.text), c.message) << c.text;
}
