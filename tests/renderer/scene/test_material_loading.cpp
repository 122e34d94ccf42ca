// Loading the thin_dielectric and mix materials and a conductor's reflectance
// (renderer/scene/scene_loader.cpp): what is accepted, and every refusal as one line naming
// file:line:col and the key. Positions are counted by hand (lines from 1 at the opening brace;
// lines 1-3 are the head, the materials start on line 4).
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

class MaterialLoading : public test::SceneFileTest {};

}  // namespace

TEST_F(MaterialLoading, ThinDielectricAndMixesAreRead) {
  SceneDesc s = load_scene(scene(R"(  "textures": {"half": {"type": "constant", "value": 0.5}},
  "materials": {
    "sheet": {"type": "thin_dielectric", "ior": 1.33, "albedo": [0.9, 0.8, 0.7]},
    "a": {"type": "mix", "materials": ["sheet", "z"], "amount": 0.25},
    "z": {"type": "diffuse"},
    "t": {"type": "mix", "materials": ["a", "z"], "amount": "half"},
    "d": {"type": "mix", "materials": ["z", "z"]}
  }
})"));
  // Materials are kept in name order: a, d, sheet, t, z.
  ASSERT_EQ(s.materials.size(), 5u);
  const Material& sheet = s.materials[2];
  EXPECT_EQ(sheet.type, MaterialType::ThinDielectric);
  EXPECT_FLOAT_EQ(sheet.ior, 1.33f);
  EXPECT_FLOAT_EQ(sheet.albedo.z, 0.7f);
  const Material& a = s.materials[0];
  EXPECT_EQ(a.type, MaterialType::Mix);
  EXPECT_EQ(a.mix[0], 2);  // "sheet"
  EXPECT_EQ(a.mix[1], 4);  // "z", defined after the mix
  EXPECT_FLOAT_EQ(a.amount, 0.25f);
  const Material& t = s.materials[3];
  EXPECT_EQ(t.mix[0], 0);  // a mix of a mix
  ASSERT_EQ(t.textures.size(), 1u);
  EXPECT_EQ(t.textures[0], (TextureBinding{MaterialParam::Amount, 0}));
  EXPECT_FLOAT_EQ(s.materials[1].amount, 0.5f);  // the default
  EXPECT_FLOAT_EQ(load_scene(scene(R"(  "materials": {"g": {"type": "thin_dielectric"}}
})"))
                      .materials[0]
                      .ior,
                  1.5f);
}

TEST_F(MaterialLoading, MixWithAnUnknownMaterial) {
  EXPECT_ERROR(scene(R"(  "materials": {
    "m": {"type": "mix", "materials": ["m2", "nope"]},
    "m2": {"type": "diffuse"}
  }
})"),
               "s.json:5:46: materials.m.materials[1] unknown material \"nope\"");
}

TEST_F(MaterialLoading, MixCycleIsRefused) {
  EXPECT_ERROR(scene(R"(  "materials": {
    "a": {"type": "mix", "materials": ["b", "d"]},
    "b": {"type": "mix", "materials": ["d", "a"]},
    "d": {"type": "diffuse"}
  }
})"),
               "s.json:6:45: materials.b.materials[1] makes a cycle of mix materials: \"a\" -> \"b\" -> \"a\"");
}

TEST_F(MaterialLoading, MixOfItselfIsACycle) {
  EXPECT_ERROR(scene(R"(  "materials": {
    "a": {"type": "mix", "materials": ["a", "d"]},
    "d": {"type": "diffuse"}
  }
})"),
               "s.json:5:40: materials.a.materials[0] makes a cycle of mix materials: \"a\" -> \"a\"");
}

TEST_F(MaterialLoading, MixAmountOutsideTheUnitInterval) {
  EXPECT_ERROR(scene(R"(  "materials": {
    "m": {"type": "mix", "materials": ["d", "d"], "amount": 1.5},
    "d": {"type": "diffuse"}
  }
})"),
               "s.json:5:61: materials.m.amount must be in [0,1], got 1.5");
  EXPECT_ERROR(scene(R"(  "materials": {
    "m": {"type": "mix", "materials": ["d", "d"], "amount": -0.1},
    "d": {"type": "diffuse"}
  }
})"),
               "s.json:5:61: materials.m.amount must be in [0,1], got -0.1");
}

TEST_F(MaterialLoading, MixOfAnEmitterIsRefused) {
  EXPECT_ERROR(scene(R"(  "materials": {
    "m": {"type": "mix", "materials": ["d", "lamp"]},
    "d": {"type": "diffuse"},
    "lamp": {"type": "emitter", "radiance": [4, 4, 4]}
  }
})"),
               "s.json:5:45: materials.m.materials[1] names the emitter \"lamp\": a mix's materials must not emit");
}

TEST_F(MaterialLoading, MixNeedsTwoMaterialNames) {
  EXPECT_ERROR(scene(R"(  "materials": {
    "m": {"type": "mix", "materials": ["d"]},
    "d": {"type": "diffuse"}
  }
})"),
               "s.json:5:39: materials.m.materials must be [\"first\", \"second\"] (two material names), got [\"d\"]");
  EXPECT_ERROR(scene(R"(  "materials": {
    "m": {"type": "mix", "materials": ["d", 3]},
    "d": {"type": "diffuse"}
  }
})"),
               "s.json:5:45: materials.m.materials[1]");
  EXPECT_ERROR(scene(R"(  "materials": {
    "m": {"type": "mix", "amount": 0.5}
  }
})"),
               "materials.m");
}

TEST_F(MaterialLoading, MixAndThinDielectricRefuseOtherMaterialsKeys) {
  EXPECT_ERROR(scene(R"(  "materials": {
    "m": {"type": "mix", "materials": ["d", "d"], "albedo": 0.5},
    "d": {"type": "diffuse"}
  }
})"),
               "s.json:5:51: materials.m.albedo");
  EXPECT_ERROR(scene(R"(  "materials": {
    "g": {"type": "thin_dielectric", "roughness": 0.2}
  }
})"),
               "s.json:5:38: materials.g.roughness");
  EXPECT_ERROR(scene(R"(  "materials": {
    "g": {"type": "thin_dielectric", "ior": 0}
  }
})"),
               "s.json:5:45: materials.g.ior must be > 0, got 0");
}

TEST_F(MaterialLoading, ConductorByReflectanceValueOrTexture) {
  SceneDesc s = load_scene(scene(R"(  "textures": {"r": {"type": "constant", "value": [0.9, 0.5, 0.1]}},
  "materials": {
    "c": {"type": "conductor", "reflectance": [0.9, 0.5, 0.1], "roughness": 0.2},
    "t": {"type": "conductor", "reflectance": "r"}
  }
})"));
  const Material& c = s.materials[0];
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(c.eta[i], 1.0f);
    EXPECT_NEAR(c.k[i] * c.k[i] / (4 + c.k[i] * c.k[i]), 0.9 - 0.4 * i, 1e-5) << i;
  }
  ASSERT_EQ(s.materials[1].textures.size(), 1u);
  EXPECT_EQ(s.materials[1].textures[0], (TextureBinding{MaterialParam::Reflectance, 0}));
  EXPECT_ERROR(scene(R"(  "materials": {
    "c": {"type": "conductor", "metal": "Au", "reflectance": 0.5}
  }
})"),
               "s.json:5:47: materials.c.reflectance cannot be combined with metal, eta or k: give one of them");
  EXPECT_ERROR(scene(R"(  "materials": {
    "c": {"type": "conductor", "reflectance": [1.5, 0, 0]}
  }
})"),
               "s.json:5:47: materials.c.reflectance");
}
