// Path regularisation (IntegratorDesc::regularize, regularized() in render/bsdf.h): which
// lobes it roughens and by how much, that the camera's own vertex is never changed, and that it
// reduces the specks of a glossy caustic.
#include "renderer/compare/image_metrics.h"
#include "renderer/render/bsdf.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;
using namespace pdrt::test;

namespace {

Material of_type(MaterialType type, float roughness) {
  Material m;
  m.type = type;
  m.roughness = roughness;
  return m;
}

float alpha(const Material& m) { return m.roughness * m.roughness; }

long long speck_count(const Image& im) {
  long long n = 0;
  for (unsigned char f : firefly_mask(im, 3)) n += f;
  return n;
}

// A diffuse floor, a glossy sphere on it (GGX alpha 0.09, the demo's) and a small, bright quad
// light above and behind it: the floor's caustic from the sphere (floor -> sphere -> light) is
// found only when a diffuse bounce happens to hit the sphere and its sharp lobe the light, a
// rare, bright sample at a few spp: specks. The camera looks down at the floor beside the
// sphere; neither the sphere, its shadow nor the light is in view.
SceneDesc caustic_scene(int size, int spp) {
  SceneDesc s = base_scene(size, size, spp);
  s.camera.position = Vec3(-1.7f, 3, 0.01f), s.camera.look_at = Vec3(-1.7f, 0, 0), s.camera.vfov_deg = 30;
  s.integrator.max_depth = 4;
  const int floor = add_material(s, diffuse(0.8f));
  Material gloss;
  gloss.name = "gloss";
  gloss.type = MaterialType::Glossy;
  gloss.albedo = Vec3(0.9f);
  gloss.roughness = 0.3f;
  const int ball = add_material(s, gloss);
  const int light = add_material(s, emitter(400.0f));
  s.shapes.push_back(quad(Vec3(-4, 0, 4), Vec3(8, 0, 0), Vec3(0, 0, -8), floor));
  s.shapes.push_back(sphere(Vec3(0, 0.6f, 0), 0.6f, ball));
  s.shapes.push_back(quad(Vec3(-0.15f, 4, -2.6f), Vec3(0.3f, 0, 0), Vec3(0, 0, 0.3f), light));  // facing down
  return s;
}

}  // namespace

// A GGX alpha below 0.3 doubles within [0.1, 0.3]; rougher lobes are left alone.
TEST(Regularize, GgxAlphaDoublesWithinPointOneToPointThree) {
  EXPECT_NEAR(alpha(regularized(of_type(MaterialType::Glossy, 0.3f))), 0.18, 1e-6);     // 0.09 -> 0.18
  EXPECT_NEAR(alpha(regularized(of_type(MaterialType::Conductor, 0.2f))), 0.1, 1e-6);   // 0.04 -> 0.1
  EXPECT_NEAR(alpha(regularized(of_type(MaterialType::Dielectric, 0.5f))), 0.3, 1e-6);  // 0.25 -> 0.3
  EXPECT_NEAR(alpha(regularized(of_type(MaterialType::CoatedDiffuse, 0.2f))), 0.1, 1e-6);
  EXPECT_EQ(regularized(of_type(MaterialType::Glossy, 0.6f)).roughness, 0.6f);  // 0.36 stays
}

// Delta lobes become rough (alpha 0.1), so that next-event estimation can reach them: a smooth
// dielectric or conductor keeps its type, a mirror becomes the GGX glossy lobe of its F0.
TEST(Regularize, DeltaLobesBecomeRoughAtAlphaPointOne) {
  for (MaterialType t : {MaterialType::Dielectric, MaterialType::Conductor}) {
    const Material r = regularized(of_type(t, 0.0f));
    EXPECT_EQ(r.type, t);
    EXPECT_NEAR(alpha(r), 0.1, 1e-6);
  }
  Material mirror = of_type(MaterialType::Mirror, 0.0f);
  mirror.albedo = Vec3(0.9f, 0.5f, 0.2f);
  const Material r = regularized(mirror);
  EXPECT_EQ(r.type, MaterialType::Glossy);
  EXPECT_EQ(r.lobe, GlossLobe::GGX);
  EXPECT_NEAR(alpha(r), 0.1, 1e-6);
  EXPECT_EQ(r.albedo.y, 0.5f);
  EXPECT_FALSE(Bsdf(r).is_delta());
}

// A Phong lobe gets the exponent of the regularised alpha (n = 2 / alpha^2 - 2).
TEST(Regularize, PhongExponentFollowsTheRegularisedAlpha) {
  Material m = of_type(MaterialType::Glossy, 0.0f);
  m.lobe = GlossLobe::Phong;
  m.exponent = 198;  // alpha 0.1 -> 0.2: exponent 48
  EXPECT_NEAR(regularized(m).exponent, 48.0, 1e-3);
  m.exponent = 10;  // alpha 0.41: left alone
  EXPECT_EQ(regularized(m).exponent, 10.0f);
}

// Diffuse and thin dielectric (whose transmission keeps its direction) are unchanged.
TEST(Regularize, DiffuseAndThinDielectricAreUnchanged) {
  for (MaterialType t : {MaterialType::Diffuse, MaterialType::ThinDielectric}) {
    const Material r = regularized(of_type(t, 0.0f));
    EXPECT_EQ(r.type, t);
    EXPECT_EQ(r.roughness, 0.0f);
  }
}

TEST(Regularize, IsOffByDefault) {
  EXPECT_FALSE(IntegratorDesc{}.regularize);
  EXPECT_FALSE(SceneDesc{}.integrator.regularize);
}

// The camera's own vertex shades with the material as given: a mirror sphere in a bright
// environment, seen directly, renders the same pixels with and without regularisation (the
// mirror is the first scattering, and the environment is hit next).
TEST(Regularize, CameraVertexIsNotRegularized) {
  Material mirror;
  mirror.type = MaterialType::Mirror;
  mirror.albedo = Vec3(0.9f);
  SceneDesc s = furnace_sphere(16, 16, 4, Vec3(0, 0, 0), mirror);
  const Image plain = render_quietly(s).image;
  s.integrator.regularize = true;
  const Image reg = render_quietly(s).image;
  EXPECT_EQ(plain.rgb, reg.rgb);
}

// The caustic scene at 16 spp has specks (pixels over 3 times their 3x3 median; 12 measured);
// regularised, the sphere's lobe is twice as wide after the floor's diffuse bounce, the caustic
// is found 4 times as often at a quarter of the value, and at most a quarter of them are left
// (3 measured).
TEST(Regularize, ReducesTheSpecksOfAGlossyCausticFourfold) {
  SceneDesc s = caustic_scene(48, 16);
  const long long plain = speck_count(render_quietly(s).image);
  s.integrator.regularize = true;
  const long long reg = speck_count(render_quietly(s).image);
  EXPECT_GE(plain, 8);
  EXPECT_LE(4 * reg, plain);
}
