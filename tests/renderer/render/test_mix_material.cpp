// The mix material (renderer/render/mix_material.h, pbrt-v4's MixMaterial): the hashed choice
// has the blended expectation (eval of two diffuse albedos, nested mixes, a rendered furnace,
// a textured amount, a textured component), its sampling routine fits the mixture pdf
// (chi-square, with a glossy component), amount 0 and 1 render exactly the components'
// images, and delta and dielectric components keep a furnace white.
#include "renderer/render/bsdf.h"
#include "renderer/render/mix_material.h"
#include "sampling/core/rng.h"
#include "tests/support/bsdf_chi_square.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace pdrt {
namespace {

using namespace pdrt::test;

Material mix_of(int a, int b, float amount) {
  Material m;
  m.type = MaterialType::Mix;
  m.mix[0] = a, m.mix[1] = b;
  m.amount = amount;
  return m;
}

Material glossy(float roughness) {
  Material m;
  m.type = MaterialType::Glossy;
  m.lobe = GlossLobe::GGX;
  m.roughness = roughness;
  m.albedo = Vec3(0.9f);
  return m;
}

Vec3 random_point(Rng& rng) {
  return {float(rng.uniform(-10, 10)), float(rng.uniform(-10, 10)), float(rng.uniform(-10, 10))};
}

// Mean over hit points of f(wo, wi) of the material each point resolves to.
double mean_eval(const std::vector<Material>& ms, int mix, int n, uint64_t seed) {
  std::vector<Bsdf> bsdfs;
  for (const Material& m : ms) bsdfs.emplace_back(m);
  const Vec3 wo = normalize(Vec3(0.3f, 0.2f, 0.9f)), wi = normalize(Vec3(-0.5f, 0.1f, 0.7f));
  Rng rng(seed);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const int k = resolve_mix(ms, mix, random_point(rng), wo, [&](int j) { return ms[size_t(j)].amount; });
    sum += bsdfs[size_t(k)].eval(wo, wi).y;
  }
  return sum / n;
}

TEST(MixMaterial, ComponentChoiceFollowsAmountAndIsReplayable) {
  EXPECT_EQ(mix_component(0.0f, 0.0f), 0);
  EXPECT_EQ(mix_component(1.0f, 0x1.fffffep-1f), 1);
  EXPECT_EQ(mix_component(0.3f, 0.29f), 1);
  EXPECT_EQ(mix_component(0.3f, 0.31f), 0);
  const Vec3 p(1, 2, 3), wo(0, 0, 1);
  EXPECT_EQ(mix_hash(p, wo, 4), mix_hash(p, wo, 4));
  EXPECT_NE(mix_hash(p, wo, 0), mix_hash(p, wo, 1));  // nested levels choose independently
  EXPECT_NE(mix_hash(p, wo, 4), mix_hash(p, Vec3(0, 1, 0), 4));
  EXPECT_LT(mix_hash(p, wo, 4), 1.0f);
}

// Lambert albedos 0.2 and 0.8 mixed by 0.3: E[f] = (0.7 * 0.2 + 0.3 * 0.8) / pi = 0.38 / pi.
TEST(MixMaterial, MixOfTwoDiffuseAlbedosEvaluatesToTheBlendedAlbedo) {
  std::vector<Material> ms = {diffuse(0.2f), diffuse(0.8f), mix_of(0, 1, 0.3f)};
  const int n = 400000;
  const double mean = mean_eval(ms, 2, n, 3);
  // One sample is 0.2/pi or 0.8/pi: standard deviation 0.6/pi sqrt(0.3 * 0.7) per sample.
  const double sigma = 0.6 / M_PI * std::sqrt(0.21 / n);
  std::printf("mix eval: %.6f, blended %.6f (sigma %.1e)\n", mean, 0.38 / M_PI, sigma);
  EXPECT_NEAR(mean, 0.38 / M_PI, 5 * sigma);
}

// mix(mix(0.1, 0.9 by 0.25), 0.7 by 0.5): (0.75 * 0.1 + 0.25 * 0.9) * 0.5 + 0.7 * 0.5 = 0.5.
TEST(MixMaterial, NestedMixesMultiplyTheirProbabilities) {
  std::vector<Material> ms = {diffuse(0.1f), diffuse(0.9f), diffuse(0.7f), mix_of(0, 1, 0.25f), mix_of(3, 2, 0.5f)};
  const int n = 400000;
  const double mean = mean_eval(ms, 4, n, 5);
  // Values 0.1, 0.9, 0.7 (/pi) with probabilities 0.375, 0.125, 0.5: variance 0.0875 / pi^2.
  const double sigma = std::sqrt(0.0875 / n) / M_PI;
  EXPECT_NEAR(mean, 0.5 / M_PI, 5 * sigma);
}

// The integrator's routine at one hit of a random point: choose by the hash, sample that
// component; pdf() the mixture (1 - a) p0 + a p1 it should follow over many hits.
struct MixedSampling {
  std::vector<Material> ms;
  std::vector<Bsdf> bsdfs;
  float amount;
  mutable Rng rng{23};
  MixedSampling(Material a, Material b, float t) : ms{a, b, mix_of(0, 1, t)}, amount(t) {
    bsdfs.emplace_back(a), bsdfs.emplace_back(b);
  }
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out) const {
    const int k = resolve_mix(ms, 2, random_point(rng), wo, [&](int) { return amount; });
    if (!bsdfs[size_t(k)].sample(wo, u1, u2, uc, out)) return false;
    out->pdf = pdf(wo, out->wi);
    return true;
  }
  float pdf(const Vec3& wo, const Vec3& wi) const {
    return (1 - amount) * bsdfs[0].pdf(wo, wi) + amount * bsdfs[1].pdf(wo, wi);
  }
};

TEST(MixMaterial, SamplingRoutineFitsTheMixturePdfWithAGlossyComponent) {
  for (float theta : {20.0f, 65.0f}) {
    const float t = theta * kPi / 180;
    const Vec3 wo(std::sin(t), 0, std::cos(t));
    MixedSampling mix(diffuse(0.5f), glossy(0.3f), 0.4f);
    const int64_t n = 400000;
    FitResult r = chi_square_fit(mix, wo, 41, n);
    std::printf("mix sampling theta %.0f: chi2 %.1f dof %.0f p %.3f\n", theta, r.statistic, r.dof, r.p);
    EXPECT_GT(r.p, 0.005) << "theta " << theta;  // 0.01 over the two angles (Sidak)
    EXPECT_EQ(r.zero_pdf_samples, 0);
    EXPECT_EQ(r.pdf_mismatches, 0);
    // The mixture pdf integrates to the probability that a sample succeeds (GGX loses the
    // directions below the horizon): 4 binomial sigma plus the quadrature's 1e-4.
    const double s = r.success_fraction;
    EXPECT_LT(s, 1.0);
    EXPECT_NEAR(r.pdf_integral, s, 4.0 * std::sqrt(s * (1 - s) / double(n)) + 1e-4);
  }
}

// A furnace sphere of the mix renders what the sphere of the blended diffuse albedo renders.
TEST(MixMaterial, RenderedFurnaceOfAMixShowsTheBlendedAlbedo) {
  const Vec3 centre(0, 0, 0);
  SceneDesc s = furnace_sphere(32, 32, 32, centre, diffuse(0.2f));
  const int b = add_material(s, diffuse(0.8f));
  s.shapes[0].material = add_material(s, mix_of(0, b, 0.3f));
  Image im = render_quietly(s).image;
  double sum = 0;
  int n = 0;
  for (auto [x, y] : pixels_inside_silhouette(s, centre, 0.8)) sum += mean_rgb(im, x, y), ++n;
  ASSERT_GT(n, 100);
  std::printf("mix furnace: %.4f (blended albedo 0.38)\n", sum / n);
  EXPECT_NEAR(sum / n, 0.38, 0.005);  // 32 spp x ~300 pixels of a 0.2 / 0.8 choice: sigma ~ 0.002
}

// The same through a texture-bound amount (a constant texture of 0.3).
TEST(MixMaterial, TexturedAmountRendersLikeTheNumber) {
  const Vec3 centre(0, 0, 0);
  SceneDesc s = furnace_sphere(32, 32, 32, centre, diffuse(0.2f));
  const int b = add_material(s, diffuse(0.8f));
  TextureDesc t;
  t.kind = TextureDesc::Kind::Constant;
  t.value = Vec3(0.3f);
  s.textures.push_back(t);
  Material m = mix_of(0, b, 0.9f);  // the texture overrides this
  m.textures.push_back({MaterialParam::Amount, 0});
  s.shapes[0].material = add_material(s, m);
  Image im = render_quietly(s).image;
  double sum = 0;
  int n = 0;
  for (auto [x, y] : pixels_inside_silhouette(s, centre, 0.8)) sum += mean_rgb(im, x, y), ++n;
  EXPECT_NEAR(sum / n, 0.38, 0.005);
}

// A component with a texture: evaluated at the hit after the choice (albedo 0.9 in the
// material, 0.2 from its constant texture), so the furnace again shows 0.38.
TEST(MixMaterial, TexturedComponentShadesWithItsTexture) {
  const Vec3 centre(0, 0, 0);
  SceneDesc s = furnace_sphere(32, 32, 32, centre, diffuse(0.9f));
  TextureDesc t;
  t.kind = TextureDesc::Kind::Constant;
  t.value = Vec3(0.2f);
  s.textures.push_back(t);
  s.materials[0].textures.push_back({MaterialParam::Albedo, 0});
  const int b = add_material(s, diffuse(0.8f));
  s.shapes[0].material = add_material(s, mix_of(0, b, 0.3f));
  Image im = render_quietly(s).image;
  double sum = 0;
  int n = 0;
  for (auto [x, y] : pixels_inside_silhouette(s, centre, 0.8)) sum += mean_rgb(im, x, y), ++n;
  EXPECT_NEAR(sum / n, 0.38, 0.005);
}

// Amount 0 and 1 choose one component outright: the images are bit for bit the components'.
TEST(MixMaterial, AmountZeroAndOneRenderExactlyTheComponents) {
  auto scene = [](int shape_material_choice, float amount) {
    SceneDesc s = base_scene(24, 24, 4);
    s.camera.position = {0, 1, 4}, s.camera.look_at = {0, 0, 0};
    const int light = add_material(s, emitter(5));
    s.shapes.push_back(quad({-1, 3, -1}, {2, 0, 0}, {0, 0, 2}, light));
    const int a = add_material(s, diffuse(0.6f)), b = add_material(s, glossy(0.3f));
    const int m = add_material(s, mix_of(a, b, amount));
    s.shapes.push_back(sphere({0, 0, 0}, 1, shape_material_choice < 0 ? m : (shape_material_choice == 0 ? a : b)));
    s.shapes.push_back(quad({-3, -1, 3}, {6, 0, 0}, {0, 0, -6}, m));
    return s;
  };
  for (int which : {0, 1}) {
    Image mixed = render_quietly(scene(-1, float(which))).image;
    SceneDesc plain = scene(which, float(which));
    plain.shapes[2].material = plain.shapes[1].material;
    Image component = render_quietly(plain).image;
    ASSERT_EQ(mixed.rgb.size(), component.rgb.size());
    double sum = 0;
    for (size_t i = 0; i < mixed.rgb.size(); ++i) {
      ASSERT_EQ(mixed.rgb[i], component.rgb[i]) << "amount " << which << " value " << i;
      sum += mixed.rgb[i];
    }
    EXPECT_GT(sum, 0);
  }
}

// Delta and dielectric components: mirror (white) + white diffuse, and glass + white diffuse,
// conserve energy whichever is chosen at each hit, so the furnace stays white.
TEST(MixMaterial, DeltaAndDielectricComponentsKeepAWhiteFurnaceWhite) {
  for (int glass_component : {0, 1}) {
    const Vec3 centre(0, 0, 0);
    SceneDesc s = furnace_sphere(24, 24, 16, centre, diffuse(1.0f));
    s.integrator.max_depth = 64;
    Material delta;
    if (glass_component) {
      delta = glass(1.5f);
    } else {
      delta.type = MaterialType::Mirror;
      delta.albedo = Vec3(1.0f);
    }
    const int d = add_material(s, delta);
    s.shapes[0].material = add_material(s, mix_of(0, d, 0.5f));
    Image im = render_quietly(s).image;
    double sum = 0;
    int n = 0;
    for (auto [x, y] : pixels_inside_silhouette(s, centre, 0.8)) sum += mean_rgb(im, x, y), ++n;
    std::printf("mix with %s: furnace %.4f\n", glass_component ? "glass" : "mirror", sum / n);
    EXPECT_NEAR(sum / n, 1.0, 0.01);
  }
}

}  // namespace
}  // namespace pdrt
