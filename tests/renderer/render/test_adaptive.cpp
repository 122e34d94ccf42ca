// Adaptive refinement by prefix extension (McCool–Fiume §5.1, Cook §6).
#include "renderer/render/adaptive_metric.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <utility>

using namespace pdrt;
using namespace pdrt::test;

namespace {

// Left: a lit diffuse sphere (noisy); right: empty black background (noise-free).
SceneDesc adaptive_scene(const char* metric, float threshold, const char* variance = "samples") {
  SceneDesc s = base_scene(48, 32, 4);
  s.camera.position = {0, 0, 6}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 30;
  s.shapes.push_back(sphere({-1.0f, 0, 0}, 0.9f, add_material(s, diffuse(0.7f))));
  s.shapes.push_back(sphere({-1.0f, 3, 2}, 0.5f, add_material(s, emitter(8.0f))));
  s.sampler.adaptive.enabled = true;
  s.sampler.adaptive.min_spp = 4, s.sampler.adaptive.max_spp = 64;
  s.sampler.adaptive.metric = value_named(kAdaptiveMetricNames, metric), s.sampler.adaptive.threshold = threshold;
  s.sampler.adaptive.variance = value_named(kAdaptiveVarianceNames, variance);
  return s;
}

// The mean sample count over the sphere (noisy) and over the empty background.
std::pair<double, double> sphere_and_background_spp(const Image& im) {
  double left = 0, right = 0;
  int nl = 0, nr = 0;
  for (int y = 0; y < im.height; ++y) {
    for (int x = 14; x < 20; ++x) left += im.samples[y * im.width + x], ++nl;
    for (int x = 40; x < 48; ++x) right += im.samples[y * im.width + x], ++nr;
  }
  return {left / nl, right / nr};
}

// Every sample count is min_spp (4) doubled some number of times, capped at max_spp (64).
void expect_prefix_lengths(const RenderResult& r) {
  int64_t total = 0;
  for (float s : r.image.samples) {
    int n = int(s);
    bool ok = n == 64;
    for (int p = 4; p < 64; p *= 2) ok = ok || n == p;
    EXPECT_TRUE(ok) << n;
    total += n;
  }
  EXPECT_EQ(total, r.stats.samples);
}

}  // namespace

TEST(Adaptive, SamplesGoWhereTheNoiseIs) {
  RenderResult r = render_quietly(adaptive_scene("relative-error", 0.02f));
  auto [sphere, background] = sphere_and_background_spp(r.image);
  EXPECT_DOUBLE_EQ(background, 4.0) << "converged background keeps min_spp";
  EXPECT_GT(sphere, 16) << "the noisy sphere refines";
  EXPECT_GT(r.stats.adaptive_rounds, 1);
}

TEST(Adaptive, ErrorPerSampleSendsSamplesToTheNoise) {
  RenderResult r = render_quietly(adaptive_scene("error-per-sample", 1.0f / 16));
  auto [sphere, background] = sphere_and_background_spp(r.image);
  EXPECT_DOUBLE_EQ(background, 4.0);
  EXPECT_GT(sphere, 16);
}

TEST(Adaptive, HalvesVarianceSendsSamplesToTheNoise) {
  RenderResult r = render_quietly(adaptive_scene("error-per-sample", 1.0f / 16, "halves"));
  auto [sphere, background] = sphere_and_background_spp(r.image);
  EXPECT_DOUBLE_EQ(background, 4.0);
  EXPECT_GT(sphere, 16);
}

// A pixel that ended with k samples holds exactly what a fixed render at k spp gives it:
// refinement only appends to the prefix, in every family.
TEST(Adaptive, RefinementOnlyExtendsPrefixes) {
  SceneDesc s = adaptive_scene("relative-error", 0.02f);
  s.camera.aperture_radius = 0.05f;  // the lens family must extend too
  RenderResult a = render_quietly(s);
  std::map<int, Image> fixed;
  int checked = 0;
  for (std::size_t i = 0; i < a.image.samples.size(); ++i) {
    int k = int(a.image.samples[i]);
    if (!fixed.count(k)) {
      SceneDesc f = s;
      f.sampler.adaptive.enabled = false;
      f.sampler.spp = k;
      fixed[k] = render_quietly(f).image;
    }
    ASSERT_EQ(0, std::memcmp(&a.image.rgb[3 * i], &fixed[k].rgb[3 * i], 3 * sizeof(float))) << "pixel " << i;
    ++checked;
  }
  EXPECT_GE(fixed.size(), 3u) << "several sample counts occur";
  EXPECT_EQ(checked, 48 * 32);
}

TEST(Adaptive, ContrastMetricRefinesEdgesAndIsDeterministicAcrossThreads) {
  SceneDesc s = adaptive_scene("contrast", 0.4f);
  RenderResult a = render_quietly(s, 1), b = render_quietly(s, 2);
  ASSERT_EQ(0, std::memcmp(a.image.rgb.data(), b.image.rgb.data(), a.image.rgb.size() * sizeof(float)));
  ASSERT_EQ(a.image.samples, b.image.samples);
  double mx = 0, mn = 1e9;
  for (float v : a.image.samples) mx = std::max<double>(mx, v), mn = std::min<double>(mn, v);
  EXPECT_EQ(mn, 4);
  EXPECT_EQ(mx, 64);
}

// Every pixel's sample count is its prefix length (box filter: every sample of the prefix
// is traced), for each metric and variance estimator.
TEST(Adaptive, SampleCountEqualsPrefixLength) {
  expect_prefix_lengths(render_quietly(adaptive_scene("relative-error", 0.02f)));
}

TEST(Adaptive, ErrorPerSampleCountEqualsPrefixLength) {
  expect_prefix_lengths(render_quietly(adaptive_scene("error-per-sample", 1.0f / 16)));
}

TEST(Adaptive, HalvesCountEqualsPrefixLength) {
  expect_prefix_lengths(render_quietly(adaptive_scene("error-per-sample", 1.0f / 16, "halves")));
}

// The image mean error-per-sample compares against is summed in a fixed order.
TEST(Adaptive, ErrorPerSampleIsDeterministicAcrossThreads) {
  SceneDesc s = adaptive_scene("error-per-sample", 1.0f / 16);
  RenderResult a = render_quietly(s, 1), b = render_quietly(s, 2);
  ASSERT_EQ(0, std::memcmp(a.image.rgb.data(), b.image.rgb.data(), a.image.rgb.size() * sizeof(float)));
  ASSERT_EQ(a.image.samples, b.image.samples);
  EXPECT_GT(a.stats.adaptive_rounds, 1);
}

SceneDesc constant_scene(const char* metric, const char* variance) {
  SceneDesc s = base_scene(16, 16, 4);
  s.environment.radiance = Vec3(0.7f);  // nothing but a constant environment
  s.sampler.adaptive.enabled = true;
  s.sampler.adaptive.min_spp = 4, s.sampler.adaptive.max_spp = 64, s.sampler.adaptive.threshold = 1e-4f;
  s.sampler.adaptive.metric = value_named(kAdaptiveMetricNames, metric);
  s.sampler.adaptive.variance = value_named(kAdaptiveVarianceNames, variance);
  return s;
}

void expect_all_at_min_spp(const SceneDesc& s) {
  RenderResult r = render_quietly(s);
  for (float n : r.image.samples) ASSERT_EQ(n, 4.0f);
  EXPECT_EQ(r.stats.adaptive_rounds, 0);
}

TEST(Adaptive, ConstantColourPixelsStopAtMinSpp) {
  for (const char* metric : {"relative-error", "contrast"}) {
    SCOPED_TRACE(metric);
    expect_all_at_min_spp(constant_scene(metric, "samples"));
  }
}

TEST(Adaptive, ErrorPerSampleStopsConstantColourPixelsAtMinSpp) {
  expect_all_at_min_spp(constant_scene("error-per-sample", "samples"));
}

TEST(Adaptive, HalvesStopConstantColourPixelsAtMinSpp) {
  expect_all_at_min_spp(constant_scene("error-per-sample", "halves"));
}

TEST(Adaptive, EachMetricHasItsOwnDefaultThreshold) {
  AdaptiveDesc ad;  // threshold 0: not given
  EXPECT_EQ(ad.metric, AdaptiveMetricKind::ErrorPerSample);
  EXPECT_DOUBLE_EQ(effective_threshold(ad), 1.0 / 16);
  ad.metric = AdaptiveMetricKind::RelativeError;
  EXPECT_DOUBLE_EQ(effective_threshold(ad), 0.01);
  ad.metric = AdaptiveMetricKind::Contrast;
  EXPECT_DOUBLE_EQ(effective_threshold(ad), 0.4);
  ad.threshold = 0.25f;
  EXPECT_DOUBLE_EQ(effective_threshold(ad), 0.25) << "a given threshold wins";
}

// The bug this guards: one default (0.01) for every metric made contrast refine everything.
TEST(Adaptive, ContrastWithoutThresholdRendersAsMitchellsDefault) {
  SceneDesc unset = adaptive_scene("contrast", 0), given = adaptive_scene("contrast", 0.4f);
  RenderResult a = render_quietly(unset), b = render_quietly(given);
  ASSERT_EQ(a.image.samples, b.image.samples);
  double background = sphere_and_background_spp(a.image).second;
  EXPECT_DOUBLE_EQ(background, 4.0) << "the black background has no contrast";
}

// Two samples, 1 and 3: the half buffers' (1 - 3)^2 / 4 equals the sample estimate s^2 / n = 2 / 2.
TEST(Adaptive, HalvesVarianceIsTheHalfMeansDifference) {
  PixelAccum p;
  p.add(Vec3(1.0f), 1.0f, Vec3(0.0f), Vec3(0.0f), 1.0f, 0);
  p.add(Vec3(3.0f), 1.0f, Vec3(0.0f), Vec3(0.0f), 1.0f, 1);
  EXPECT_NEAR(p.half_variance_of_mean(), 1.0, 1e-6);
  EXPECT_NEAR(p.variance_of_mean(), 1.0, 1e-6);
}
