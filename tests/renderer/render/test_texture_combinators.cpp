// Scale, mix, invert and power textures (renderer/render/texture_set.cpp): each evaluated
// against its closed form, through nested inputs and a checkerboard, and the per-lookup work
// bound (texture_evaluation_cost) that keeps their recursion finite.
#include "renderer/render/texture_set.h"
#include "renderer/scene/texture_desc.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;

namespace {

TextureDesc constant(Vec3 v) {
  TextureDesc t;
  t.kind = TextureDesc::Kind::Constant;
  t.value = v;
  return t;
}

TextureInput ref(int i) {
  TextureInput in;
  in.texture = i;
  return in;
}

TextureInput val(Vec3 v) {
  TextureInput in;
  in.value = v;
  return in;
}

TextureCoords at(float u, float v) {
  TextureCoords tc;
  tc.u = u, tc.v = v;
  return tc;
}

void expect_vec(const Vec3& a, const Vec3& b) {
  for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(a[i], b[i]) << "channel " << i;
}

}  // namespace

TEST(TextureCombinators, ScaleMultipliesPerChannel) {
  SceneDesc s;
  s.textures.push_back(constant({0.5f, 0.25f, 1.0f}));
  TextureDesc t;
  t.kind = TextureDesc::Kind::Scale;
  t.tex = ref(0), t.scale = val({2.0f, 0.5f, 0.0f});
  s.textures.push_back(t);
  t.tex = val(Vec3(3.0f)), t.scale = ref(0);  // either input may be the texture
  s.textures.push_back(t);
  TextureSet set(s);
  expect_vec(set.eval(1, at(0.3f, 0.4f)), {1.0f, 0.125f, 0.0f});
  expect_vec(set.eval(2, at(0.3f, 0.4f)), {1.5f, 0.75f, 3.0f});
}

TEST(TextureCombinators, MixLerpsByTheAmountsFirstChannel) {
  SceneDesc s;
  s.textures.push_back(constant({0.1f, 0.2f, 0.3f}));
  s.textures.push_back(constant({0.25f, 0.9f, 0.9f}));  // amount: only its first channel counts
  TextureDesc t;
  t.kind = TextureDesc::Kind::Mix;
  t.tex1 = ref(0), t.tex2 = val({0.9f, 0.8f, 0.7f}), t.amount = ref(1);
  s.textures.push_back(t);
  TextureDesc d;  // pbrt-v4's defaults: tex1 0, tex2 1, amount 0.5
  d.kind = TextureDesc::Kind::Mix;
  s.textures.push_back(d);
  TextureSet set(s);
  const Vec3 m = set.eval(2, at(0, 0));
  EXPECT_FLOAT_EQ(m.x, 0.75f * 0.1f + 0.25f * 0.9f);
  EXPECT_FLOAT_EQ(m.y, 0.75f * 0.2f + 0.25f * 0.8f);
  EXPECT_FLOAT_EQ(m.z, 0.75f * 0.3f + 0.25f * 0.7f);
  expect_vec(set.eval(3, at(0, 0)), Vec3(0.5f));
}

TEST(TextureCombinators, InvertIsOneMinusClampedAtZero) {
  SceneDesc s;
  s.textures.push_back(constant({0.2f, 1.0f, 0.0f}));
  TextureDesc sc;
  sc.kind = TextureDesc::Kind::Scale;
  sc.tex = ref(0), sc.scale = val(Vec3(2.0f));  // 0.4, 2, 0: pbrt-v4 inverts after scaling
  s.textures.push_back(sc);
  TextureDesc t;
  t.kind = TextureDesc::Kind::Invert;
  t.tex = ref(1);
  s.textures.push_back(t);
  TextureSet set(s);
  expect_vec(set.eval(2, at(0, 0)), {0.6f, 0.0f, 1.0f});
}

TEST(TextureCombinators, PowerRemapsPbrtRoughnessToPerceptual) {
  SceneDesc s;
  s.textures.push_back(constant({0.0625f, 0.25f, 0.0f}));
  TextureDesc t;
  t.kind = TextureDesc::Kind::Power;
  t.tex = ref(0), t.exponent = 0.25f;
  s.textures.push_back(t);
  TextureSet set(s);
  // pbrt roughness r, remapped: alpha = sqrt(r); pdrt roughness = sqrt(alpha) = r^(1/4).
  const Vec3 p = set.eval(1, at(0, 0));
  EXPECT_FLOAT_EQ(p.x, 0.5f);
  EXPECT_NEAR(p.y, std::pow(0.25, 0.25), 1e-7);
  EXPECT_EQ(p.z, 0.0f);
  // Bound to roughness, the material gets the remapped value, clamped to [0, 1].
  Material m;
  m.type = MaterialType::Conductor;
  Material out = set.apply(m, {{MaterialParam::Roughness, 1}}, at(0, 0));
  EXPECT_FLOAT_EQ(out.roughness, 0.5f);
}

TEST(TextureCombinators, InputsReachThroughACheckerboard) {
  SceneDesc s;
  TextureDesc c;
  c.kind = TextureDesc::Kind::Checkerboard;
  c.color0 = val(Vec3(0.2f)), c.color1 = val(Vec3(0.6f));
  s.textures.push_back(c);
  TextureDesc t;
  t.kind = TextureDesc::Kind::Scale;
  t.tex = ref(0), t.scale = val(Vec3(0.5f));
  s.textures.push_back(t);
  TextureSet set(s);
  expect_vec(set.eval(1, at(0.5f, 0.5f)), Vec3(0.1f));  // even check
  expect_vec(set.eval(1, at(1.5f, 0.5f)), Vec3(0.3f));  // odd check
}

TEST(TextureCombinators, ReflectanceBindingGivesTheConductorOfThatReflectance) {
  SceneDesc s;
  s.textures.push_back(constant({0.9f, 0.5f, 0.1f}));
  TextureSet set(s);
  Material m;
  m.type = MaterialType::Conductor;
  Material out = set.apply(m, {{MaterialParam::Reflectance, 0}}, at(0, 0));
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(out.eta[c], 1.0f);
    const float k = out.k[c];
    EXPECT_NEAR(k * k / (4 + k * k), 0.9 - 0.4 * c, 1e-5) << c;  // R0 of eta 1, k
  }
}

TEST(TextureCombinators, EvaluationCostCountsEveryVisitedCombinator) {
  // A chain of mixes of the previous texture with itself doubles the work per level.
  std::vector<TextureDesc> ts = {constant(Vec3(0.5f))};
  for (int i = 1; i <= 12; ++i) {
    TextureDesc t;
    t.kind = TextureDesc::Kind::Mix;
    t.tex1 = ref(i - 1), t.tex2 = ref(i - 1);
    ts.push_back(t);
  }
  std::vector<long long> cost = texture_evaluation_cost(ts, {});
  EXPECT_EQ(cost[0], 0);
  EXPECT_EQ(cost[1], 1);
  EXPECT_EQ(cost[2], 3);
  EXPECT_EQ(cost[12], (1 << 12) - 1);
  EXPECT_GT(cost[12], kMaxTextureEvaluation);
  EXPECT_LE(cost[9], kMaxTextureEvaluation);  // 511
  // A checkerboard is a loop: it adds nothing and takes the larger input.
  TextureDesc c;
  c.kind = TextureDesc::Kind::Checkerboard;
  c.color0 = ref(3), c.color1 = ref(1);
  ts.push_back(c);
  EXPECT_EQ(texture_evaluation_cost(ts, {}).back(), 7);
}
