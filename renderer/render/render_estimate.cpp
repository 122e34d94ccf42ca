#include "renderer/render/render_estimate.h"

#include "renderer/render/pixel_renderer.h"
#include "renderer/render/process_cpu_time.h"
#include "renderer/render/thread_sampler_states.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <utility>

namespace pdrt {

namespace {

constexpr int kBlock = 4;  // pixels per side of a calibration block
// Seconds it may take: kept samples cost nothing, so they may take longer and average over
// the 10-30 ms spells in which a shared machine runs a fifth slower.
constexpr double kCalibrationTime = 0.05, kKeptCalibrationTime = 0.1;
constexpr double kCalibrationShare = 1.0 / 2;  // of the render's samples it may take
constexpr int kWarmUpBlocks = 8;

// The ranks' wall seconds per sample combined (their rates add up), and the sum of `count`.
std::pair<double, double> combined(double seconds_per_sample, double count, const ProcessGroup& group) {
  const double mine[2] = {seconds_per_sample, count};
  std::vector<std::byte> bytes(sizeof mine);
  std::memcpy(bytes.data(), mine, sizeof mine);
  double rate = 0, total = 0;
  for (const std::vector<std::byte>& b : group.all_gather(bytes)) {
    double r[2];
    std::memcpy(r, b.data(), sizeof r);
    rate += r[0] > 0 ? 1 / r[0] : 0;
    total += r[1];
  }
  return {rate > 0 ? 1 / rate : 0, total};
}

// Point k of the R2 sequence (Roberts 2018) in [0, 1)^2.
std::pair<double, double> r2(uint64_t k) {
  return {std::fmod(0.5 + 0.7548776662466927 * double(k), 1.0), std::fmod(0.5 + 0.5698402909980532 * double(k), 1.0)};
}

// The pixels of blocks [b0, b1).
int64_t pixels_in(const std::vector<PixelRect>& blocks, std::size_t b0, std::size_t b1) {
  int64_t n = 0;
  for (std::size_t k = b0; k < b1; ++k) n += int64_t(blocks[k].width()) * blocks[k].height();
  return n;
}

}  // namespace

std::vector<PixelRect> calibration_blocks(const PixelRect& region, bool kept, const std::function<bool(int, int)>& mine,
                                          std::size_t most) {
  std::vector<PixelRect> out;
  if (region.empty()) return out;
  if (!kept) {
    // Anywhere, overlapping as they fall: scratch films hold each block apart.
    for (std::size_t k = 0; k < most; ++k) {
      const auto [u, v] = r2(k);
      const int x = region.x0 + int(u * std::max(1, region.width() - kBlock + 1)),
                y = region.y0 + int(v * std::max(1, region.height() - kBlock + 1));
      out.push_back({x, std::min(x + kBlock, region.x1), y, std::min(y + kBlock, region.y1)});
    }
    return out;
  }
  const int cx0 = region.x0 / kBlock, cy0 = region.y0 / kBlock;
  const int nx = (region.x1 - 1) / kBlock - cx0 + 1, ny = (region.y1 - 1) / kBlock - cy0 + 1;
  const std::size_t cells = std::size_t(nx) * std::size_t(ny);
  std::vector<uint8_t> seen(cells, 0);
  std::size_t visited = 0;
  // R2 points land on every cell (equidistributed); past 8 draws per cell the rest go in order.
  for (uint64_t k = 0; out.size() < most && visited < cells; ++k) {
    std::size_t c;
    if (k < 8 * uint64_t(cells)) {
      const auto [u, v] = r2(k);
      c = std::size_t(std::min(int(v * ny), ny - 1)) * std::size_t(nx) + std::size_t(std::min(int(u * nx), nx - 1));
    } else {
      c = std::size_t(k - 8 * uint64_t(cells));
      if (c >= cells) break;
    }
    if (seen[c]) continue;
    seen[c] = 1, ++visited;
    const int x = (cx0 + int(c % std::size_t(nx))) * kBlock, y = (cy0 + int(c / std::size_t(nx))) * kBlock;
    const PixelRect b{std::max(x, region.x0), std::min(x + kBlock, region.x1), std::max(y, region.y0),
                      std::min(y + kBlock, region.y1)};
    if (mine(b.x0, b.y0)) out.push_back(b);
  }
  return out;
}

double render_scratch_blocks(const PixelRenderer& pixels, const Sampler& sampler, const Sampler* decider,
                             const std::vector<PixelRect>& blocks, std::size_t b0, std::size_t b1, int64_t spp) {
  std::atomic<int64_t> busy_ns{0};
  ThreadSamplerStates states(sampler, decider);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(b0, b1), [&](const tbb::blocked_range<std::size_t>& r) {
    const auto t0 = std::chrono::steady_clock::now();
    ThreadSamplerStates::Lease held = states.lease();
    const int m = pixels.mode == Reconstruction::Splat ? pixels.splat_margin() : 0;
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const PixelRect& b = blocks[k];
      PixelRenderer p = pixels;
      p.ox = b.x0 - m, p.oy = b.y0 - m;
      Film film(b.width() + 2 * m, b.height() + 2 * m),
          decide(decider ? b.width() + 2 * m : 0, decider ? b.height() + 2 * m : 0);
      for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x)
          p.run(x, y, 0, spp, film, decider ? &decide : nullptr, held.sampler(), held.decider());
    }
    busy_ns += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
  });
  return 1e-9 * double(busy_ns.load());
}

RenderEstimate estimate_render(const std::vector<PixelRect>& blocks, const EstimatePlan& plan,
                               const CalibrationRender& render, const ProcessGroup& group) {
  using clock = std::chrono::steady_clock;
  const double threads = double(std::max(1, plan.threads));
  const double limit = plan.kept ? kKeptCalibrationTime : kCalibrationTime;
  RenderEstimate e;
  e.samples = plan.samples;
  if (plan.ends.empty()) return e;
  // (A small film may have few blocks: a third of them then, so that some are timed.)
  const std::size_t warm = blocks.size() >= kWarmUpBlocks + 4 ? kWarmUpBlocks : blocks.size() / 3;
  // Untimed: the first touches of textures (loaded on demand) and caches, paid once per render.
  if (warm > 0) render(0, warm, plan.ends[0]);
  int64_t taken = pixels_in(blocks, 0, warm) * plan.ends[0];  // samples the blocks took, warm-up included
  // Samples it may take in all: half the render's, or 4 blocks' first pass, so that every
  // render is timed (when it has them).
  const double allowed = std::max(4.0 * kBlock * kBlock * double(plan.ends[0]), plan.samples * kCalibrationShare);
  const auto t0 = clock::now();
  const double cpu0 = process_cpu_seconds();
  double idle = 0;  // the largest round's wall time in which a thread had no block
  std::size_t largest = 0, level_blocks = blocks.size() - warm;
  // Level k takes blocks [warm, warm + level_blocks) from the pass end before ends[k] to
  // ends[k], in rounds of doubling size, the last one cut to what the time left allows at the
  // rate so far; the next level takes the blocks this one finished.
  for (std::size_t k = 0; k < plan.ends.size() && level_blocks > 0; ++k) {
    const int64_t from = k == 0 ? 0 : plan.ends[k - 1], width = plan.ends[k] - from;
    const double cap = std::min(
        double(level_blocks), std::floor((allowed - double(e.calibration_samples)) / double(kBlock * kBlock * width)));
    std::size_t n = 0;
    for (std::size_t next = std::size_t(std::clamp(cap, 0.0, 4.0)); next > n;) {
      const double before = e.calibration_seconds;
      const double busy = render(warm + n, warm + next, plan.ends[k]);
      const int64_t pixels = pixels_in(blocks, warm + n, warm + next);
      e.calibration_busy_seconds += busy;
      e.calibration_samples += pixels * width;
      if (k == 0) e.calibration_pixels += int(pixels);
      e.calibration_seconds = std::chrono::duration<double>(clock::now() - t0).count();
      if (next - n >= largest)
        largest = next - n, idle = std::max(0.0, e.calibration_seconds - before - busy / threads);
      n = next;
      const double per_block = e.calibration_seconds / double(e.calibration_samples) * double(kBlock * kBlock * width);
      const double fit = (limit - e.calibration_seconds) / per_block;
      next = n + std::size_t(std::clamp(std::min(fit, cap - double(n)), 0.0, double(n)));
    }
    if (n > 0) e.calibration_passes = int(k) + 1;
    if (double(n) < double(level_blocks)) break;  // out of time or samples
    level_blocks = n;
  }
  e.calibration_cpu_seconds = process_cpu_seconds() - cpu0;
  taken += e.calibration_samples;
  // The rate: the threads' busy time per sample over the threads, not the wall time's, which
  // counts each round's start and end, when threads wait for blocks (cheap scenes' calibrations
  // last ~10 ms in 9 rounds, and with it their 256-spp renders were estimated at up to 2.4x
  // their time). Busy time is wall time inside a block, so it still sees other processes' load.
  // Each of the passes' parallel loops then costs what the largest round idled (a 1-spp
  // render's one pass lasts a few ms, which the wait for a sleeping thread can double).
  const double rate =
      e.calibration_samples > 0 ? e.calibration_busy_seconds / threads / double(e.calibration_samples) : 0;
  const auto [per_sample, all_taken] = combined(rate, plan.kept ? double(taken) : 0.0, group);
  e.seconds_per_sample = per_sample;
  e.loop_seconds = idle, e.loops = plan.loops;
  e.calibration_kept = plan.kept;
  e.seconds = std::max(0.0, plan.samples - all_taken) * e.seconds_per_sample + double(plan.loops) * idle;
  return e;
}

}  // namespace pdrt
