// The time estimate's calibration (render_estimate.h): its pixels' samples are the render's
// first passes, kept in the film (unless splatted), so a calibrated render is the uncalibrated one
// bit for bit whichever blocks and passes its time allowed.
#include "renderer/render/render_estimate.h"
#include "renderer/render/renderer.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

namespace pdrt {
namespace {

using test::lit_sphere;

RenderResult render_scene(const SceneDesc& s, bool estimate, int threads) {
  auto sampler = make_scene_sampler(s.sampler, s.film);
  RenderOptions o;
  o.quiet = true, o.threads = threads;
  if (estimate) o.on_estimate = [](const RenderEstimate&) {};
  return render(s, *sampler, o);
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

void expect_calibration_keeps_the_image(const SceneDesc& s, bool kept) {
  const RenderResult without = render_scene(s, false, 1), with = render_scene(s, true, 2);
  EXPECT_GT(with.stats.estimate.calibration_samples, 0);
  EXPECT_EQ(with.stats.estimate.calibration_kept, kept);
  EXPECT_TRUE(same_bits(with.image.rgb, without.image.rgb));
  EXPECT_TRUE(same_bits(with.image.samples, without.image.samples));
  EXPECT_EQ(with.stats.samples, without.stats.samples);  // the calibration's samples counted once
}

// The calibrated pixels keep their first pass (every pixel's samples in index order; on this
// 40 x 24 film the calibration takes some of the pixels at 1 spp and all of them from 4 on), at
// 1, 2, 4, 16 spp, with every sampler (those that order pixels too) and two seeds.
TEST(RenderEstimate, CalibratedRenderIsTheUncalibratedOneBitForBit) {
  for (int spp : {1, 2, 4, 16})
    for (const std::string& sampler : sampler_names())
      for (uint64_t seed : {1u, 29u}) {
        SCOPED_TRACE(sampler + " at " + std::to_string(spp) + " spp, seed " + std::to_string(seed));
        SceneDesc s = lit_sphere(spp, sampler.c_str());
        s.sampler.seed = seed;
        expect_calibration_keeps_the_image(s, true);
      }
}

// Rank reconstruction takes a pass's candidates by the pass's end: the calibration's are the
// first pass's.
TEST(RenderEstimate, CalibratedRankRenderIsTheUncalibratedOneBitForBit) {
  SceneDesc s = lit_sphere(16, "poisson");
  s.film.filter.reconstruction = Reconstruction::Rank;
  expect_calibration_keeps_the_image(s, true);
}

// Splatting calibrates in scratch films: the film's order of contributions is untouched.
TEST(RenderEstimate, CalibratedSplattedRenderIsTheUncalibratedOneBitForBit) {
  SceneDesc s = lit_sphere(8, "poisson");
  s.film.filter.reconstruction = Reconstruction::Splat;
  expect_calibration_keeps_the_image(s, false);
}

// Adaptive: the calibration takes round 0's first pass.
TEST(RenderEstimate, CalibratedAdaptiveRenderIsTheUncalibratedOneBitForBit) {
  SceneDesc s = lit_sphere(64, "sobol");
  s.sampler.adaptive.enabled = true, s.sampler.adaptive.min_spp = 16, s.sampler.adaptive.max_spp = 64;
  expect_calibration_keeps_the_image(s, true);
}

// Kept blocks: 4 x 4 on the grid of multiples of 4, cut by the region, each once: all of them
// cover every pixel of the region exactly once; the first is the R2 sequence's first point,
// the region's middle.
TEST(RenderEstimate, CalibrationBlocksCoverTheRegionOnceEach) {
  const PixelRect region{3, 37, 5, 22};
  const std::vector<PixelRect> all = calibration_blocks(
      region, true, [](int, int) { return true; }, 1000);
  std::vector<int> hits(std::size_t(region.width()) * region.height(), 0);
  for (const PixelRect& b : all) {
    ASSERT_FALSE(b.empty());
    EXPECT_TRUE(b.x0 >= region.x0 && b.x1 <= region.x1 && b.y0 >= region.y0 && b.y1 <= region.y1);
    EXPECT_EQ(b.x1 - 1 - (b.x1 - 1) % 4, b.x0 - b.x0 % 4) << "one grid cell";
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0; x < b.x1; ++x) ++hits[std::size_t(y - region.y0) * region.width() + (x - region.x0)];
  }
  for (int h : hits) ASSERT_EQ(h, 1);
  EXPECT_EQ(all.front().x0, 20);
  EXPECT_EQ(all.front().y0, 12);
  EXPECT_EQ(calibration_blocks(
                region, true, [](int, int) { return true; }, 5)
                .size(),
            5u);
  const auto left = calibration_blocks(
      region, true, [](int x, int) { return x < 16; }, 1000);
  for (const PixelRect& b : left) EXPECT_LT(b.x0, 16);
  EXPECT_EQ(left.size(), 4u * 5u);  // columns 3, 4-7, 8-11, 12-15; rows 5-7, 8-11, 12-15, 16-19, 20-21
}

// The rate is the blocks' busy time over the threads, whatever the rounds' wall time: a fake
// calibration whose blocks take 10 ns of busy time a sample and whose rounds each wait 3 ms
// (threads that wake late). The wait becomes the cost of each of the passes' loops instead.
TEST(RenderEstimate, RateIsTheBlocksBusyTimeOverTheThreadsAndTheWaitIsPerLoop) {
  const std::vector<PixelRect> blocks = calibration_blocks(
      PixelRect{0, 64, 0, 64}, true, [](int, int) { return true; }, 1000);
  int rounds = 0;
  const CalibrationRender fake = [&](std::size_t b0, std::size_t b1, int64_t spp) {
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
    ++rounds;
    return 1e-8 * double(b1 - b0) * 16 * double(spp);
  };
  const LocalProcessGroup alone;
  const EstimatePlan plan{{8}, 64.0 * 64 * 256, true, 4, 6};
  const RenderEstimate e = estimate_render(blocks, plan, fake, alone);
  ASSERT_GT(e.calibration_samples, 0);
  const int timed = rounds - 1;  // the first call is the untimed warm-up
  ASSERT_GE(timed, 3);
  EXPECT_NEAR(e.seconds_per_sample, 1e-8 / 4, 1e-15);
  EXPECT_NEAR(e.calibration_busy_seconds, 1e-8 * double(e.calibration_samples), 1e-12);
  // The largest round's wall time less its busy time over the threads: at least its 3 ms wait,
  // and one round's, not the rounds' sum (each of the others took at least its 3 ms too).
  EXPECT_GE(e.loop_seconds, 0.003 - 1e-8 * double(e.calibration_samples) / 4);
  EXPECT_LE(e.loop_seconds, e.calibration_seconds - 0.003 * (timed - 1));
  EXPECT_EQ(e.loops, 6);
  const double taken = double(e.calibration_samples) + 8 * 16 * 8;  // the 8 untimed warm-up blocks
  EXPECT_NEAR(e.seconds, (plan.samples - taken) * e.seconds_per_sample + 6 * e.loop_seconds, 1e-9);
}

// With time left after every block's first pass, the calibration takes the blocks it finished
// through the next passes, in order, each block from the last pass's end (so their samples are
// the passes'); it stops at half the render's samples.
TEST(RenderEstimate, TimeLeftTakesTheFinishedBlocksThroughTheNextPasses) {
  const std::vector<PixelRect> blocks = calibration_blocks(
      PixelRect{0, 64, 0, 64}, true, [](int, int) { return true; }, 1000);
  ASSERT_EQ(blocks.size(), 256u);
  struct Call {
    std::size_t b0, b1;
    int64_t end;
  };
  std::vector<Call> calls;
  const CalibrationRender fake = [&](std::size_t b0, std::size_t b1, int64_t end) {
    calls.push_back({b0, b1, end});
    return 1e-9 * double(b1 - b0);
  };
  const LocalProcessGroup alone;
  // Blocks through [0, 8), [8, 16), [16, 32): 100 blocks of the third level fill the half.
  const double half = 248.0 * 16 * 16 + 100.0 * 16 * 16;
  const RenderEstimate e = estimate_render(blocks, EstimatePlan{{8, 16, 32, 64}, 2 * half, true, 2, 4}, fake, alone);
  EXPECT_EQ(e.calibration_passes, 3);
  EXPECT_EQ(double(e.calibration_samples), half);
  EXPECT_EQ(e.calibration_pixels, 248 * 16);
  // Each level's calls cover its blocks once, in order: all but the 8 warm-up blocks, then the
  // same, then the first 100 of them.
  const std::vector<std::pair<int64_t, std::size_t>> levels{{8, 256}, {16, 256}, {32, 108}};
  std::size_t c = 1;  // calls[0]: the warm-up
  ASSERT_EQ(calls[0].b0, 0u);
  ASSERT_EQ(calls[0].b1, 8u);
  for (const auto& [end, last] : levels) {
    std::size_t at = 8;
    for (; c < calls.size() && calls[c].end == end; ++c) {
      EXPECT_EQ(calls[c].b0, at);
      at = calls[c].b1;
    }
    EXPECT_EQ(at, last) << "the level to " << end;
  }
  EXPECT_EQ(c, calls.size());
}

}  // namespace
}  // namespace pdrt
