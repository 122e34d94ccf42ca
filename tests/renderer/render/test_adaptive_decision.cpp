// Kirk & Arvo (1991): adaptive stopping biases the estimate when the same samples decide and
// estimate; sampler.adaptive.decision "split" keeps them apart.
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

using namespace pdrt;
using namespace pdrt::test;

namespace {

constexpr int kSize = 32;
constexpr float kLe = 1.0f;
constexpr double kCoverage = 1.0 / 64;

// Every pixel sees a centred emitter square 1/8 of its side (1/64 of its area), away from the origin.
SceneDesc subpixel_emitters(const char* decision, uint64_t seed, const char* sampler_type = "random") {
  SceneDesc s = base_scene(kSize, kSize, 4);
  const Vec3 c{7, -3, 2};
  const float D = 5, vfov = 30;
  s.camera.position = c + Vec3{0, 0, D}, s.camera.look_at = c, s.camera.vfov_deg = vfov;
  const float p = 2 * D * std::tan(vfov * 3.14159265f / 360) / kSize, e = p / 8;
  int m = add_material(s, emitter(kLe));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      float X = c.x + (x + 0.5f - kSize / 2) * p, Y = c.y + (y + 0.5f - kSize / 2) * p;
      s.shapes.push_back(quad({X - e / 2, Y - e / 2, c.z}, {e, 0, 0}, {0, e, 0}, m));
    }
  s.sampler.seed = seed;
  s.sampler.type = sampler_type;
  s.sampler.adaptive.enabled = true;
  s.sampler.adaptive.min_spp = 4, s.sampler.adaptive.max_spp = 256;
  s.sampler.adaptive.decision = value_named(kAdaptiveDecisionNames, decision);
  return s;
}

// Mean pixel value over 8 seeds relative to the analytic coverage x radiance, and its standard error.
std::pair<double, double> relative_mean(const char* decision, const char* sampler = "random") {
  double s1 = 0, s2 = 0;
  int n = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    Image im = render_quietly(subpixel_emitters(decision, seed, sampler)).image;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        double v = mean_rgb(im, x, y) / (kCoverage * kLe);
        s1 += v, s2 += v * v, ++n;
      }
  }
  double mean = s1 / n, se = std::sqrt(std::max(0.0, s2 / n - mean * mean) / (n - 1));
  std::printf("%s, decision %s: mean / analytic = %.4f +- %.4f\n", sampler, decision, mean, se);
  return {mean, se};
}

}  // namespace

TEST(AdaptiveDecision, SharedDecisionIsBiasedOnSubpixelEmitters) {
  auto [mean, se] = relative_mean("shared");
  EXPECT_GT(std::abs(mean - 1), 3 * se);
}

TEST(AdaptiveDecision, SplitDecisionIsUnbiasedOnSubpixelEmitters) {
  auto [mean, se] = relative_mean("split");
  EXPECT_LE(std::abs(mean - 1), 3 * se);
}

// The decision samples come from an independent sampler, so the estimate's samples are a full
// prefix of the scene's sampler: unbiased for the stratified samplers too (poisson since its
// values are randomised over seeds, issue 15; before, 2.457 at 2 spp and 0.912 at 64).
TEST(AdaptiveDecision, SplitDecisionIsUnbiasedForStratifiedSamplers) {
  for (const char* sampler : {"jitter", "poisson", "sobol"}) {
    auto [mean, se] = relative_mean("split", sampler);
    EXPECT_LE(std::abs(mean - 1), 3 * se) << sampler;
  }
}

TEST(AdaptiveDecision, SplitIsBitIdenticalAtOneAndTwoThreads) {
  SceneDesc s = subpixel_emitters("split", 3);
  Image a = render_quietly(s, 1).image, b = render_quietly(s, 2).image;
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  EXPECT_EQ(0, std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(a.samples.data(), b.samples.data(), a.samples.size() * sizeof(float)));
}
