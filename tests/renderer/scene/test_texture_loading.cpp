// Loading "textures", texture-valued material parameters, mesh "uvs" and OBJ "vt"
// (renderer/scene/scene_loader.cpp): what is accepted, and every refusal as one line naming
// file:line:col and the key. Positions are counted by hand (lines from 1 at the opening brace).
#include "renderer/scene/scene_loader.h"
#include "sampling/core/errors.h"
#include "tests/support/scene_file_fixture.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace pdrt;

namespace {

class TextureLoading : public test::SceneFileTest {};

}  // namespace

TEST_F(TextureLoading, TexturesAndBindingsAreRead) {
  file("wood.png", "x");
  SceneDesc s = load_scene(scene(R"(  "textures": {
    "checks": {"type": "checkerboard", "scale": [8, 4], "color0": "wood", "color1": 0.2},
    "wood": {"type": "image", "file": "wood.png", "filter": "none", "wrap": "mirror", "encoding": "linear", "scale": 2},
    "half": {"type": "constant", "value": 0.5}
  },
  "materials": {"a": {"type": "glossy", "albedo": "checks", "roughness": "half"},
                "b": {"type": "conductor", "metal": "Au", "roughness": "wood"}}
})"));
  ASSERT_EQ(s.textures.size(), 3u);
  const TextureDesc& c = s.textures[0];
  EXPECT_EQ(c.kind, TextureDesc::Kind::Checkerboard);
  EXPECT_EQ(c.scale_u, 8);
  EXPECT_EQ(c.scale_v, 4);
  EXPECT_EQ(c.color0.texture, 2);  // "wood", defined after it (textures are kept in name order)
  EXPECT_EQ(c.color1.texture, -1);
  EXPECT_EQ(c.color1.value.y, 0.2f);
  const TextureDesc& w = s.textures[2];
  EXPECT_EQ(w.filter, TextureFilter::None);
  EXPECT_EQ(w.wrap, TextureWrap::Mirror);
  EXPECT_EQ(w.encoding, TextureEncoding::Linear);
  EXPECT_EQ(w.scale_u, 2);
  EXPECT_EQ(w.file, dir() / "wood.png");
  EXPECT_EQ(s.textures[1].value.z, 0.5f);
  ASSERT_EQ(s.materials[0].textures.size(), 2u);
  EXPECT_EQ(s.materials[0].textures[0], (TextureBinding{MaterialParam::Roughness, 1}));
  EXPECT_EQ(s.materials[0].textures[1], (TextureBinding{MaterialParam::Albedo, 0}));
  EXPECT_EQ(s.materials[1].textures[0], (TextureBinding{MaterialParam::Roughness, 2}));
}

TEST_F(TextureLoading, ImageDefaultsAreBilinearRepeatAndAutomaticEncoding) {
  file("t.exr", "x");
  SceneDesc s = load_scene(scene(R"(  "textures": {"t": {"type": "image", "file": "t.exr"}}
})"));
  EXPECT_EQ(s.textures[0].filter, TextureFilter::Bilinear);
  EXPECT_EQ(s.textures[0].wrap, TextureWrap::Repeat);
  EXPECT_EQ(s.textures[0].encoding, TextureEncoding::Auto);
}

TEST_F(TextureLoading, UnknownTextureInAMaterial) {
  EXPECT_ERROR(scene(R"(  "textures": {"checks": {"type": "constant", "value": 0.5}},
  "materials": {"a": {"type": "diffuse", "albedo": "cheks"}}
})"),
               "s.json:5:52: materials.a.albedo unknown texture \"cheks\" (textures: \"checks\")");
}

TEST_F(TextureLoading, TextureNameWithoutATexturesSection) {
  EXPECT_ERROR(scene(R"(  "materials": {"a": {"type": "dielectric", "roughness": "r"}}
})"),
               "s.json:4:58: materials.a.roughness unknown texture \"r\" (the scene has no \"textures\")");
}

TEST_F(TextureLoading, UnknownTextureInACheckerboard) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "checkerboard", "color0": "nope", "color1": 0}}
})"),
               "s.json:4:56: textures.c.color0 unknown texture \"nope\"");
}

TEST_F(TextureLoading, CheckerboardOfItselfIsACycle) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "checkerboard", "color0": 1, "color1": "c"}}
})"),
               "s.json:4:69: textures.c.color1 makes a cycle of textures: \"c\" -> \"c\"");
}

TEST_F(TextureLoading, LongerCycleIsRefused) {
  EXPECT_ERROR(scene(R"(  "textures": {
    "a": {"type": "checkerboard", "color0": "b", "color1": 0},
    "b": {"type": "checkerboard", "color0": 0, "color1": "a"}}
})"),
               "textures.b.color1 makes a cycle of textures: \"a\" -> \"b\" -> \"a\"");
}

TEST_F(TextureLoading, UnknownTextureType) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "marble"}}
})"),
               "s.json:4:30: textures.c.type must be one of constant, checkerboard, image, scale, mix, invert, power, "
               "got \"marble\"");
}

TEST_F(TextureLoading, EmptyTextureName) {
  EXPECT_ERROR(scene(R"(  "textures": {"": {"type": "constant", "value": 1}}
})"),
               "s.json:4:16: textures[\"\"] texture name must not be empty");
}

TEST_F(TextureLoading, ConstantValueOutOfRange) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "constant", "value": [0.5, 1.5, 0]}}
})"),
               "s.json:4:51: textures.c.value must have components in [0,1], got [0.5,1.5,0]");
}

TEST_F(TextureLoading, CheckerboardColourOfWrongType) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "checkerboard", "color0": true, "color1": 0}}
})"),
               "s.json:4:56: textures.c.color0 must be an array of 3 numbers, got true");
}

TEST_F(TextureLoading, CheckerboardNeedsBothColours) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "checkerboard", "color0": 1}}
})"),
               "textures.c missing required key \"color1\"");
}

TEST_F(TextureLoading, NonPositiveScale) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "checkerboard", "scale": [4, 0], "color0": 1, "color1": 0}}
})"),
               "s.json:4:59: textures.c.scale[1] must be > 0, got 0");
}

TEST_F(TextureLoading, ScaleOfThreeNumbers) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "checkerboard", "scale": [1, 2, 3], "color0": 1, "color1": 0}}
})"),
               "s.json:4:55: textures.c.scale must be a number or [su, sv], got [1,2,3]");
}

TEST_F(TextureLoading, BadFilterName) {
  file("t.png", "x");
  EXPECT_ERROR(
      scene(R"(  "textures": {"t": {"type": "image", "file": "t.png", "filter": "point"}}
})"),
      "s.json:4:66: textures.t.filter must be one of none, bilinear, trilinear, ewa, anisotropic, got \"point\"");
}

TEST_F(TextureLoading, BadWrapName) {
  file("t.png", "x");
  EXPECT_ERROR(scene(R"(  "textures": {"t": {"type": "image", "file": "t.png", "wrap": "periodic"}}
})"),
               "s.json:4:64: textures.t.wrap must be one of repeat, clamp, black, mirror, got \"periodic\"");
}

TEST_F(TextureLoading, BadEncodingName) {
  file("t.png", "x");
  EXPECT_ERROR(scene(R"(  "textures": {"t": {"type": "image", "file": "t.png", "encoding": "gamma"}}
})"),
               "s.json:4:68: textures.t.encoding must be one of auto, srgb, linear, got \"gamma\"");
}

TEST_F(TextureLoading, MissingImageFile) {
  EXPECT_ERROR(scene(R"(  "textures": {"t": {"type": "image", "file": "nowhere.png"}}
})"),
               "s.json:4:47: textures.t.file cannot open \"nowhere.png\"");
}

TEST_F(TextureLoading, ImageKeysOnCheckerboardAreUnknown) {
  EXPECT_ERROR(scene(R"(  "textures": {"c": {"type": "checkerboard", "file": "x.png", "color0": 1, "color1": 0}}
})"),
               "s.json:4:46: textures.c.file unknown key (expected one of: type, scale, color0, color1)");
}

TEST_F(TextureLoading, MaterialColourOfWrongType) {
  EXPECT_ERROR(scene(R"(  "materials": {"a": {"type": "diffuse", "albedo": 7}}
})"),
               "s.json:4:52: materials.a.albedo must be an array of 3 numbers, got 7");
}

TEST_F(TextureLoading, UvsCountMustMatchTheVertices) {
  EXPECT_ERROR(scene(R"(  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [0, 1, 2],
               "uvs": [[0, 0], [1, 0]], "material": "m"}]
})"),
               "s.json:6:23: objects[0].uvs must have one [u, v] per vertex (3), got 2");
}

TEST_F(TextureLoading, UvMustBeAPair) {
  EXPECT_ERROR(scene(R"(  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [0, 1, 2],
               "uvs": [[0, 0], [1, 0, 0], [0, 1]], "material": "m"}]
})"),
               "s.json:6:32: objects[0].uvs[1] must be [u, v], got [1,0,0]");
}

TEST_F(TextureLoading, UvBeyondFloatRangeIsRefused) {
  EXPECT_ERROR(scene(R"(  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [0, 1, 2],
               "uvs": [[0, 0], [1, 1e999], [0, 1]], "material": "m"}]
})"),
               "s.json:6:36: objects[0].uvs[1][1] must be a finite number, got 1e999");
}

TEST_F(TextureLoading, UvThatIsNotANumber) {
  EXPECT_ERROR(scene(R"(  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"type": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [0, 1, 2],
               "uvs": [[0, 0], [1, "NaN"], [0, 1]], "material": "m"}]
})"),
               "s.json:6:36: objects[0].uvs[1][1] must be a number, got \"NaN\"");
}

TEST_F(TextureLoading, QuadGetsCornerUvs) {
  SceneDesc s = load_scene(scene(R"(  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"type": "quad", "corner": [0, 0, 0], "edge1": [1, 0, 0], "edge2": [0, 1, 0], "material": "m"}]
})"));
  ASSERT_EQ(s.shapes[0].mesh.uvs.size(), 4u);
  EXPECT_EQ(s.shapes[0].mesh.uvs[1][0], 1.0f);
  EXPECT_EQ(s.shapes[0].mesh.uvs[3][1], 1.0f);
}

TEST_F(TextureLoading, ObjTexcoordIndexOutOfRange) {
  file("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n");
  EXPECT_ERROR(scene(R"(  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"type": "obj", "file": "m.obj", "material": "m"}]
})"),
               "m.obj:5: face texture coordinate index 2 out of range (1 texture coordinates)");
}

TEST_F(TextureLoading, ObjTexcoordThatIsNotANumber) {
  file("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 nan\nf 1/1 2/1 3/1\n");
  EXPECT_ERROR(scene(R"(  "materials": {"m": {"type": "diffuse"}},
  "objects": [{"type": "obj", "file": "m.obj", "material": "m"}]
})"),
               "m.obj:4: texture coordinate \"nan\" is not a finite number");
}

TEST_F(TextureLoading, ScaleMixInvertAndPowerAreRead) {
  SceneDesc s = load_scene(scene(R"(  "textures": {
    "img": {"type": "constant", "value": 0.5},
    "s": {"type": "scale", "tex": "img", "scale": 2},
    "m": {"type": "mix", "tex1": "s", "tex2": [0.1, 0.2, 0.3], "amount": "img"},
    "i": {"type": "invert", "tex": "m"},
    "p": {"type": "power", "tex": "i", "exponent": 0.25},
    "d": {"type": "mix"}
  },
  "materials": {"a": {"type": "glossy", "roughness": "p"}}
})"));
  // Name order: d, i, img, m, p, s.
  ASSERT_EQ(s.textures.size(), 6u);
  const TextureDesc& d = s.textures[0];
  EXPECT_EQ(d.kind, TextureDesc::Kind::Mix);  // pbrt-v4's defaults: tex1 0, tex2 1, amount 0.5
  EXPECT_EQ(d.tex1.value.x, 0.0f);
  EXPECT_EQ(d.tex2.value.x, 1.0f);
  EXPECT_EQ(d.amount.value.x, 0.5f);
  EXPECT_EQ(s.textures[1].kind, TextureDesc::Kind::Invert);
  EXPECT_EQ(s.textures[1].tex.texture, 3);
  const TextureDesc& m = s.textures[3];
  EXPECT_EQ(m.tex1.texture, 5);
  EXPECT_EQ(m.tex2.value.z, 0.3f);
  EXPECT_EQ(m.amount.texture, 2);
  EXPECT_EQ(s.textures[4].kind, TextureDesc::Kind::Power);
  EXPECT_EQ(s.textures[4].exponent, 0.25f);
  const TextureDesc& sc = s.textures[5];
  EXPECT_EQ(sc.kind, TextureDesc::Kind::Scale);
  EXPECT_EQ(sc.tex.texture, 2);
  EXPECT_EQ(sc.scale.value.y, 2.0f);  // scale inputs may exceed 1
  EXPECT_EQ(s.materials[0].textures[0], (TextureBinding{MaterialParam::Roughness, 4}));
}

TEST_F(TextureLoading, CycleThroughScaleAndMixIsRefused) {
  EXPECT_ERROR(scene(R"(  "textures": {
    "a": {"type": "scale", "tex": "b"},
    "b": {"type": "mix", "tex1": 0, "amount": "a"}}
})"),
               "s.json:6:47: textures.b.amount makes a cycle of textures: \"a\" -> \"b\" -> \"a\"");
  EXPECT_ERROR(scene(R"(  "textures": {"p": {"type": "power", "tex": "p", "exponent": 2}}
})"),
               "s.json:4:46: textures.p.tex makes a cycle of textures: \"p\" -> \"p\"");
}

TEST_F(TextureLoading, CombinatorValuesOutOfRange) {
  EXPECT_ERROR(scene(R"(  "textures": {"s": {"type": "scale", "tex": 1, "scale": -2}}
})"),
               "s.json:4:58: textures.s.scale must be >= 0, got -2");
  EXPECT_ERROR(scene(R"(  "textures": {"s": {"type": "scale", "tex": [1, -1, 0]}}
})"),
               "s.json:4:46: textures.s.tex must have components >= 0");
  EXPECT_ERROR(scene(R"(  "textures": {"m": {"type": "mix", "amount": 1.5}}
})"),
               "s.json:4:47: textures.m.amount must be in [0,1], got 1.5");
  EXPECT_ERROR(scene(R"(  "textures": {"p": {"type": "power", "tex": 1, "exponent": 0}}
})"),
               "s.json:4:61: textures.p.exponent must be > 0, got 0");
  EXPECT_ERROR(scene(R"(  "textures": {"p": {"type": "power", "tex": 1}}
})"),
               "textures.p");
  EXPECT_ERROR(scene(R"(  "textures": {"i": {"type": "invert"}}
})"),
               "textures.i");
  EXPECT_ERROR(scene(R"(  "textures": {"i": {"type": "invert", "tex": 1, "exponent": 2}}
})"),
               "s.json:4:50: textures.i.exponent");
}

// l(k) mixes l(k-1) with itself: 2^k - 1 nodes per lookup. l10 (1023) is accepted, l11 is not.
TEST_F(TextureLoading, TextureGraphsTooCostlyToEvaluateAreRefused) {
  std::string t = "  \"textures\": {\n    \"l0\": {\"type\": \"constant\", \"value\": 0.5}";
  for (int k = 1; k <= 11; ++k)
    t += ",\n    \"l" + std::to_string(k) + "\": {\"type\": \"mix\", \"tex1\": \"l" + std::to_string(k - 1) +
         "\", \"tex2\": \"l" + std::to_string(k - 1) + "\"}";
  // l0 is on line 5, so l11 on line 16, its object at column 12.
  EXPECT_ERROR(scene(t + "\n  }\n}\n"),
               "s.json:16:12: textures.l11 evaluates 2047 scale/mix/invert/power nodes per lookup (at most 1024)");
  std::string ok = "  \"textures\": {\n    \"l0\": {\"type\": \"constant\", \"value\": 0.5}";
  for (int k = 1; k <= 10; ++k)
    ok += ",\n    \"l" + std::to_string(k) + "\": {\"type\": \"mix\", \"tex1\": \"l" + std::to_string(k - 1) +
          "\", \"tex2\": \"l" + std::to_string(k - 1) + "\"}";
  EXPECT_EQ(load_scene(scene(ok + "\n  }\n}\n")).textures.size(), 11u);
}
