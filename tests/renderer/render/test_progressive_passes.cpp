// Progressive passes (issue 33 item 5): every pass covers the whole frame, so a render stopped
// after a pass holds every pixel at that pass's spp, and under filter-weighted reconstruction
// ("importance": a pixel accumulates only its own samples, in index order, in packets of four
// that no pass boundary splits) it is the uninterrupted render at that spp, bit for bit.
#include "renderer/render/progressive_passes.h"
#include "renderer/render/renderer.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <vector>

namespace pdrt {
namespace {

using test::lit_sphere;

// Renders `s`, cancelling once the pass that reaches `stop_at` spp is complete (0: never).
// `estimate`: the time estimate's calibration runs first (render_estimate.h).
RenderResult render_stopped_at(const SceneDesc& s, int64_t stop_at, int threads = 0, bool estimate = false) {
  auto sampler = make_scene_sampler(s.sampler, s.film);
  std::atomic<bool> cancel{false};
  RenderOptions o;
  o.quiet = true, o.threads = threads, o.cancel = &cancel;
  if (estimate) o.on_estimate = [](const RenderEstimate&) {};
  o.on_pass = [&](int64_t spp) {
    if (spp == stop_at) cancel = true;
  };
  return render(s, *sampler, o);
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(ProgressivePasses, SppDoublesFromEightToTheLastPass) {
  std::vector<int64_t> ends;
  for (int64_t done = 0; done < 256; done = next_pass_end(done, 256)) ends.push_back(next_pass_end(done, 256));
  EXPECT_EQ(ends, (std::vector<int64_t>{8, 16, 32, 64, 128, 256}));
  EXPECT_EQ(pass_count(256), 6);
  EXPECT_EQ(next_pass_end(0, 1), 1);  // fewer samples than a first pass: one pass
  EXPECT_EQ(next_pass_end(0, 6), 6);
  EXPECT_EQ(next_pass_end(8, 12), 12);
  EXPECT_EQ(next_pass_end(8, 20), 16);
  EXPECT_EQ(next_pass_end(16, 20), 20);  // the last pass ends at the spp, not a power of two
}

TEST(ProgressivePasses, StoppedAfterTheFirstPassEveryPixelHasItsSpp) {
  const RenderResult r = render_stopped_at(lit_sphere(64, "sobol"), 8);
  EXPECT_TRUE(r.stats.partial);
  EXPECT_EQ(r.stats.spp_complete, 8);
  EXPECT_DOUBLE_EQ(r.stats.spp_mean, 8.0);
  for (float n : r.image.samples) ASSERT_EQ(n, 8.0f) << "a pixel without the first pass's samples";
}

// Every sampler family's prefixes, at 1 and 2 threads.
TEST(ProgressivePasses, StoppedAtAPassBoundaryIsTheRenderAtThatSppBitForBit) {
  for (const char* sampler : {"random", "jitter", "sobol", "poisson"})
    for (int threads : {1, 2}) {
      const RenderResult stopped = render_stopped_at(lit_sphere(256, sampler), 16, threads);
      const RenderResult whole = render_stopped_at(lit_sphere(16, sampler), 0, threads);
      EXPECT_TRUE(stopped.stats.partial);
      EXPECT_FALSE(whole.stats.partial);
      EXPECT_EQ(stopped.stats.spp_complete, 16);
      EXPECT_TRUE(same_bits(stopped.image.rgb, whole.image.rgb)) << sampler << ", " << threads << " threads";
      EXPECT_TRUE(same_bits(stopped.image.samples, whole.image.samples)) << sampler;
    }
}

TEST(ProgressivePasses, ACompleteRenderReachesItsSppInEveryPixel) {
  const RenderResult r = render_stopped_at(lit_sphere(24, "jitter"), 0);
  EXPECT_FALSE(r.stats.partial);
  EXPECT_EQ(r.stats.spp_complete, 24);
  for (float n : r.image.samples) ASSERT_EQ(n, 24.0f);
}

// The time limit stops the render as a cancel does: here the first pass ends long before the
// 1 s limit (a 40x24 image at 8 spp), and the pass waits for the deadline to pass, so the next
// pass stops at its first tile and the image is the first pass's (the time estimate's
// calibration, which this render runs, took part of it: render_estimate.h).
TEST(ProgressivePasses, TimeLimitStopsBetweenPassesWithEveryPixelAtTheSppReached) {
  const SceneDesc s = lit_sphere(4096, "sobol");
  auto sampler = make_scene_sampler(s.sampler, s.film);
  RenderOptions o;
  o.quiet = true, o.time_limit = 1.0;
  std::chrono::steady_clock::time_point built;
  o.on_estimate = [&](const RenderEstimate&) { built = std::chrono::steady_clock::now(); };
  o.on_pass = [&](int64_t spp) {
    if (spp != 8) return;
    while (std::chrono::steady_clock::now() < built + std::chrono::duration<double>(o.time_limit)) {}
  };
  const RenderResult r = render(s, *sampler, o);
  EXPECT_TRUE(r.stats.partial);
  EXPECT_EQ(r.stats.spp_complete, 8);
  EXPECT_GT(r.stats.estimate.calibration_samples, 0);
  for (float n : r.image.samples) ASSERT_EQ(n, 8.0f);
  EXPECT_TRUE(same_bits(r.image.rgb, render_stopped_at(lit_sphere(8, "sobol"), 0).image.rgb));
}

// The calibration takes its blocks through as many passes as its time allows (on this 40 x 24
// film, every block to 64 spp and more); stopped after the first or second pass, those blocks
// are put back as they were at its end, with every sampler, and in both films under adaptive
// "split" too.
TEST(ProgressivePasses, CalibratedRenderStoppedAtAPassBoundaryIsTheRenderAtThatSppBitForBit) {
  SceneDesc split = lit_sphere(256, "sobol");
  split.film.filter.reconstruction = Reconstruction::Importance;
  split.sampler.adaptive.enabled = true, split.sampler.adaptive.min_spp = 128, split.sampler.adaptive.max_spp = 256;
  split.sampler.adaptive.decision = AdaptiveDecision::Split;
  std::vector<SceneDesc> scenes{split};
  for (const std::string& sampler : sampler_names()) scenes.push_back(lit_sphere(256, sampler.c_str()));
  for (const SceneDesc& s : scenes)
    for (int64_t stop : {8, 16}) {
      SCOPED_TRACE((s.sampler.adaptive.enabled ? "split" : s.sampler.type) + ", stopped at " + std::to_string(stop));
      const RenderResult calibrated = render_stopped_at(s, stop, 2, true);
      const RenderResult plain = render_stopped_at(s, stop, 1, false);
      EXPECT_GT(calibrated.stats.estimate.calibration_passes, 2);
      EXPECT_TRUE(calibrated.stats.partial);
      EXPECT_EQ(calibrated.stats.spp_complete, stop);
      EXPECT_TRUE(same_bits(calibrated.image.rgb, plain.image.rgb));
      EXPECT_TRUE(same_bits(calibrated.image.samples, plain.image.samples));
      EXPECT_EQ(calibrated.stats.samples, plain.stats.samples);
    }
}

// Adaptive rendering: round 0 runs in the same passes, so a stop after its first pass leaves
// every pixel at that pass's spp.
TEST(ProgressivePasses, AdaptiveRoundZeroStoppedAfterItsFirstPassHasEveryPixelAtItsSpp) {
  SceneDesc s = lit_sphere(16, "sobol");
  s.sampler.adaptive.enabled = true, s.sampler.adaptive.min_spp = 16, s.sampler.adaptive.max_spp = 64;
  const RenderResult r = render_stopped_at(s, 8);
  EXPECT_TRUE(r.stats.partial);
  EXPECT_EQ(r.stats.spp_complete, 8);
  for (float n : r.image.samples) ASSERT_EQ(n, 8.0f);
}

}  // namespace
}  // namespace pdrt
