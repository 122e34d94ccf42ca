// Light selection by estimated contribution at the shading point (light BVH with the
// environment on the same footing; issue 14 defect 4).
#include "renderer/render/embree_scene.h"
#include "renderer/render/light_set.h"
#include "sampling/analysis/incomplete_gamma.h"
#include "sampling/core/rng.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace pdrt;
using namespace pdrt::test;

namespace {

Vec3 random_unit(Rng& rng) {
  double z = 1 - 2 * rng.uniform(), r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * M_PI * rng.uniform();
  return Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
}

// Emitters of every kind, scaled by `scale` about the origin and then moved by `offset`:
// one- and two-sided quads facing up, down and sideways, spheres of several sizes, a
// moving quad, and (optionally) the environment.
SceneDesc many_lights(float scale, Vec3 offset, bool environment) {
  SceneDesc s = base_scene(8, 8, 1);
  auto at = [&](Vec3 p) { return p * scale + offset; };
  s.shapes.push_back(
      quad(at({-4, 0, -4}), Vec3(0, 0, 8) * scale, Vec3(8, 0, 0) * scale, add_material(s, diffuse(0.5f))));
  const int one = add_material(s, emitter(3)), two = add_material(s, emitter(0.5f, true)),
            hot = add_material(s, emitter(40));
  s.shapes.push_back(quad(at({-1, 2, -1}), Vec3(2, 0, 0) * scale, Vec3(0, 0, 2) * scale, one));          // down
  s.shapes.push_back(quad(at({2, 0.5f, 1}), Vec3(0, 0, 1) * scale, Vec3(1, 0, 0) * scale, one));         // up
  s.shapes.push_back(quad(at({-3, 0.2f, 2}), Vec3(0, 1, 0) * scale, Vec3(0, 0, 1) * scale, two));        // sideways
  s.shapes.push_back(quad(at({3, 1, -3}), Vec3(0.3f, 0, 0) * scale, Vec3(0, 0.3f, 0.3f) * scale, hot));  // tilted
  s.shapes.push_back(sphere(at({0, 1, 3}), 0.2f * scale, hot));
  s.shapes.push_back(sphere(at({-2, 3, -2}), 0.05f * scale, hot));
  s.shapes.push_back(sphere(at({1.5f, 0.7f, -1}), 0.4f * scale, one));
  ShapeDesc moving = quad(at({0, 1.5f, -3}), Vec3(0.5f, 0, 0) * scale, Vec3(0, 0, 0.5f) * scale, one);
  MotionKey k0, k1;
  k1.time = 1, k1.translate = Vec3(1, 0.5f, 0) * scale;
  moving.motion = {k0, k1};
  s.shapes.push_back(moving);
  if (environment) s.environment.radiance = Vec3(0.2f, 0.3f, 0.4f);
  return s;
}

}  // namespace

// Over all lights the selection probabilities sum to 1 (or are all 0), at random points and
// normals in and around a scene far from the origin, at scales 1e-3 .. 1e3; select() reports
// exactly the pmf select_pmf() gives for its choice (MIS weights use the latter).
TEST(LightSelection, PmfSumsToOneAwayFromTheOriginAtEveryScale) {
  for (float scale : {1e-3f, 1.0f, 1e3f})
    for (float off : {0.0f, 10.0f, 1000.0f})
      for (bool env : {false, true}) {
        SceneDesc s = many_lights(scale, Vec3(off, -0.5f * off, 0.25f * off) * scale, env);
        EmbreeDevice device;
        EmbreeScene scene(s, device);
        TextureSet textures(scene.desc());
        LightSet lights(scene, textures);
        ASSERT_EQ(lights.light_count(), 2u * 5 + 3 + (env ? 1 : 0));
        Rng rng(11);
        int nonzero = 0;
        for (int i = 0; i < 200; ++i) {
          Vec3 p = (Vec3(float(rng.uniform(-5, 5)), float(rng.uniform(-1, 4)), float(rng.uniform(-5, 5))) * scale) +
                   Vec3(off, -0.5f * off, 0.25f * off) * scale;
          Vec3 n = random_unit(rng);
          double sum = 0;
          for (std::size_t l = 0; l < lights.light_count(); ++l) {
            float pm = lights.selector().select_pmf(p, n, l);
            ASSERT_GE(pm, 0.0f);
            sum += pm;
          }
          if (sum == 0) continue;
          ++nonzero;
          ASSERT_NEAR(sum, 1.0, 1e-4) << "scale " << scale << " offset " << off << " point " << i;
          for (float u : {0.0f, 0.3f, 0.77f, 0.999f}) {
            std::size_t l;
            float pm;
            ASSERT_TRUE(lights.selector().select(p, n, u, &l, &pm));
            ASSERT_EQ(pm, lights.selector().select_pmf(p, n, l));
          }
        }
        EXPECT_GT(nonzero, 190) << "points see some light";
      }
}

// sample()'s choices have the frequencies pmf() states (chi-square, 200k picks per point).
TEST(LightSelection, PickFrequenciesMatchThePmf) {
  SceneDesc s = many_lights(1, Vec3(30, 5, -20), true);
  EmbreeDevice device;
  EmbreeScene scene(s, device);
  TextureSet textures(scene.desc());
  LightSet lights(scene, textures);
  Rng rng(5);
  const int kPicks = 200000;
  for (int point = 0; point < 4; ++point) {
    Vec3 p = Vec3(float(rng.uniform(-4, 4)), float(rng.uniform(0, 2)), float(rng.uniform(-4, 4))) + Vec3(30, 5, -20);
    Vec3 n = random_unit(rng);
    std::vector<int> count(lights.light_count(), 0);
    for (int i = 0; i < kPicks; ++i) {
      std::size_t l;
      float pm;
      if (lights.selector().select(p, n, float(rng.uniform()), &l, &pm)) ++count[l];
    }
    // Bins expected to hold >= 20 picks; the rest pooled into one bin.
    double chi2 = 0, pooled_e = 0, pooled_o = 0;
    int bins = 0;
    for (std::size_t l = 0; l < count.size(); ++l) {
      double e = kPicks * double(lights.selector().select_pmf(p, n, l));
      if (e < 20) {
        pooled_e += e, pooled_o += count[l];
        continue;
      }
      chi2 += (count[l] - e) * (count[l] - e) / e, ++bins;
    }
    if (pooled_e >= 20)
      chi2 += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e, ++bins;
    else
      EXPECT_LT(pooled_o, 60) << "lights of pmf ~0 are (almost) never picked";
    ASSERT_GE(bins, 3);
    double pv = chi_square_p_value(chi2, bins - 1);
    EXPECT_GT(pv, 1e-4) << "point " << point << ": chi2 " << chi2 << " over " << bins << " bins";
  }
}

// Beside a dim light and far from a bright one, the dim one is picked most: it delivers
// about 25x the bright one's irradiance there although it has 1/10000 of its power. (A
// global power CDF picks it 1 time in 10^4.) The far light keeps a non-zero probability.
TEST(LightSelection, NearDimLightGetsMostPicksBesideIt) {
  SceneDesc s = base_scene(8, 8, 1);
  s.shapes.push_back(
      quad({-0.1f, 0.3f, -0.1f}, {0.2f, 0, 0}, {0, 0, 0.2f}, add_material(s, emitter(1))));  // 0.04 W/sr-ish
  s.shapes.push_back(quad({40, 30, -1}, {2, 0, 0}, {0, 0, 2}, add_material(s, emitter(100))));
  EmbreeDevice device;
  EmbreeScene scene(s, device);
  TextureSet textures(scene.desc());
  LightSet lights(scene, textures);
  ASSERT_EQ(lights.light_count(), 4u);
  const Vec3 p(0.02f, 0, 0.03f), n(0, 1, 0);
  const double dim = lights.selector().select_pmf(p, n, 0) + lights.selector().select_pmf(p, n, 1);
  const double bright = lights.selector().select_pmf(p, n, 2) + lights.selector().select_pmf(p, n, 3);
  EXPECT_GT(dim, 0.8);
  EXPECT_GT(bright, 1e-3);
  int dim_picks = 0;
  for (int i = 0; i < 1000; ++i) {
    LightSample ls;
    if (lights.sample(p, n, 0, (i + 0.5f) / 1000, {0.5, 0.5}, &ls)) dim_picks += ls.x.p.y < 1;
  }
  EXPECT_GT(dim_picks, 800);
}

// The environment's share does not grow with the scene: under a quad light, over a floor of
// 1 x 1 or 100 x 100, it is the same, and the light gets most picks there.
TEST(LightSelection, EnvironmentShareDoesNotGrowWithTheScene) {
  double share[2];
  for (int big = 0; big < 2; ++big) {
    SceneDesc s = base_scene(8, 8, 1);
    const float half = big ? 50.0f : 0.5f;
    s.shapes.push_back(quad({-half, 0, -half}, {0, 0, 2 * half}, {2 * half, 0, 0}, add_material(s, diffuse(0.6f))));
    s.shapes.push_back(quad({-1, 3, -1}, {2, 0, 0}, {0, 0, 2}, add_material(s, emitter(6))));
    s.environment.radiance = Vec3(0.06f);
    EmbreeDevice device;
    EmbreeScene scene(s, device);
    TextureSet textures(scene.desc());
    LightSet lights(scene, textures);
    share[big] = lights.selector().select_pmf({0.2f, 0, 0.1f}, {0, 1, 0}, lights.environment_id());
  }
  EXPECT_EQ(share[0], share[1]);
  EXPECT_LT(share[1], 0.2);
  EXPECT_GT(share[1], 0.01);
}

namespace {

struct QuadLight {
  float x0, x1, z0, z1, h, radiance;
};

// A diffuse plane y = 0 (albedo rho) seen from above at W x W pixels covering [-0.5, 0.5]^2,
// under downward-facing quad lights, in an environment of radiance env; direct light only.
// Per pixel: the rendered value and the analytic rho (env (1 - sum F) + sum L F) at its centre.
struct LitPlane {
  std::vector<double> value, expected;
};

LitPlane lit_plane(const std::vector<QuadLight>& ql, float env, uint64_t seed, int spp, int W) {
  const float rho = 0.8f;
  SceneDesc s = base_scene(W, W, spp);
  s.sampler.seed = seed;
  s.camera.position = {0, 0.5f, 0}, s.camera.look_at = {0, 0, 0}, s.camera.up = {0, 0, -1};
  s.camera.vfov_deg = 90;
  s.shapes.push_back(quad({-3, 0, -3}, {0, 0, 6}, {6, 0, 0}, add_material(s, diffuse(rho))));
  for (const QuadLight& q : ql)
    s.shapes.push_back(
        quad({q.x0, q.h, q.z0}, {q.x1 - q.x0, 0, 0}, {0, 0, q.z1 - q.z0}, add_material(s, emitter(q.radiance))));
  s.environment.radiance = Vec3(env);
  s.integrator.max_depth = 1;
  Image im = render_quietly(s).image;
  LitPlane out;
  for (int y = 0; y < W; ++y)
    for (int x = 0; x < W; ++x) {
      double cx = (x + 0.5) / W - 0.5, cz = (y + 0.5) / W - 0.5, sumF = 0, e = 0;
      for (const QuadLight& q : ql) {
        double F = rect_form_factor(cx, cz, q.x0, q.x1, q.z0, q.z1, q.h);
        sumF += F, e += q.radiance * F;
      }
      out.value.push_back(mean_rgb(im, x, y));
      out.expected.push_back(rho * (e + env * (1 - sumF)));
    }
  return out;
}

double mean_of(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m += x;
  return m / v.size();
}

}  // namespace

// Two quad lights of different size, height and radiance: pixels at 20 points of the plane
// match the analytic irradiance within 3 % at 256 spp, the single-light test's tolerance.
TEST(LightSelection, TwoQuadLightsMatchAnalyticIrradiance) {
  const int W = 64;
  LitPlane r = lit_plane({{-0.4f, 0.1f, -0.3f, 0.2f, 0.6f, 2}, {0.3f, 0.5f, 0.1f, 0.4f, 0.55f, 6}}, 0, 7, 256, W);
  int checked = 0;
  for (float px : {-0.35f, -0.1f, 0.0f, 0.2f, 0.4f})
    for (float pz : {-0.4f, -0.05f, 0.1f, 0.35f}) {
      int x = int((px + 0.5f) * W), y = int((pz + 0.5f) * W), i = y * W + x;
      EXPECT_NEAR(r.value[i], r.expected[i], 0.03 * r.expected[i]) << "pixel " << x << "," << y;
      ++checked;
    }
  EXPECT_EQ(checked, 20);
  EXPECT_NEAR(mean_of(r.value), mean_of(r.expected), 0.005 * mean_of(r.expected)) << "image mean";
}

// An environment and two small lights, direct light with MIS: the mean over 8 seeds equals
// the analytic value within 4 standard errors (and the standard error is below 0.5 %).
TEST(LightSelection, EnvironmentAndSmallLightsStayUnbiased) {
  const std::vector<QuadLight> ql = {{-0.2f, -0.05f, -0.1f, 0.05f, 0.6f, 20}, {0.25f, 0.35f, 0.2f, 0.3f, 0.7f, 40}};
  std::vector<double> means;
  double expected = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    LitPlane r = lit_plane(ql, 0.5f, seed, 8, 32);
    means.push_back(mean_of(r.value)), expected = mean_of(r.expected);
  }
  double mu = 0, var = 0;
  for (double m : means) mu += m;
  mu /= means.size();
  for (double m : means) var += (m - mu) * (m - mu);
  const double se = std::sqrt(var / (means.size() - 1) / means.size());
  EXPECT_LT(se, 0.005 * expected);
  EXPECT_NEAR(mu, expected, 4 * se + 1e-4 * expected) << "se " << se;
}

// pbrt-v4's rule (EnvironmentSampling::Compensated, set by every pbrt import): a constant
// environment is no light to sample. Escaping rays still see it, and BSDF sampling
// finds it at MIS weight 1 (environment_pdf 0); every light sample lands on an emitter.
TEST(LightSelection, ConstantEnvironmentLeftToBsdfSamplingIsNoLight) {
  for (const bool sampled : {true, false}) {
    SceneDesc s = many_lights(1, Vec3(0.0f), true);
    s.integrator.environment_sampling = sampled ? EnvironmentSampling::Full : EnvironmentSampling::Compensated;
    EmbreeDevice device;
    EmbreeScene scene(s, device);
    TextureSet textures(scene.desc());
    LightSet lights(scene, textures);
    SCOPED_TRACE(sampled ? "sampled" : "left to BSDF sampling");
    EXPECT_TRUE(lights.has_environment());
    EXPECT_EQ(lights.environment_id(), lights.light_count() - (sampled ? 1 : 0));
    const Vec3 ref(0.3f, 0, 0.2f), n(0, 1, 0);
    const float pdf = lights.environment_pdf(ref, n, normalize(Vec3(0.2f, 1, 0.1f)));
    if (sampled)
      EXPECT_GT(pdf, 0.0f);
    else
      EXPECT_EQ(pdf, 0.0f);
    Rng rng(3);
    int at_infinity = 0;
    for (int i = 0; i < 4000; ++i) {
      LightSample ls;
      if (lights.sample(ref, n, 0, float(rng.uniform()), {rng.uniform(), rng.uniform()}, &ls) && ls.at_infinity)
        ++at_infinity;
    }
    if (sampled)
      EXPECT_GT(at_infinity, 0);
    else
      EXPECT_EQ(at_infinity, 0);
  }
}
