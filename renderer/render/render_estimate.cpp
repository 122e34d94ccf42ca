#include "renderer/render/render_estimate.h"

#include "renderer/render/pixel_renderer.h"
#include "renderer/render/process_cpu_time.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>

namespace pdrt {

namespace {

constexpr int kBlock = 4;                      // pixels per side of a calibration block
constexpr int64_t kCalibrationSpp = 8;         // samples per pixel (fewer when the render has fewer)
constexpr double kCalibrationTime = 0.05;      // seconds it may take
constexpr double kCalibrationShare = 1.0 / 2;  // of the render's samples it may take
constexpr int kWarmUpBlocks = 8;

// Block k's top-left pixel: the R2 sequence over the region.
void block_origin(const PixelRect& region, int k, int* x, int* y) {
  const double u = std::fmod(0.5 + 0.7548776662466927 * k, 1.0), v = std::fmod(0.5 + 0.5698402909980532 * k, 1.0);
  *x = region.x0 + int(u * std::max(1, region.width() - kBlock + 1));
  *y = region.y0 + int(v * std::max(1, region.height() - kBlock + 1));
}

// Renders blocks [k0, k1), each pixel's samples [0, spp), into films of their own (with the
// splats' margin); the sampler states are made once, as a render's tiles share a thread's.
void render_blocks(const PixelRenderer& pixels, const Sampler& sampler, const Sampler* decider, const PixelRect& region,
                   int k0, int k1, int64_t spp) {
  PixelSampleState ps(sampler);
  std::optional<PixelSampleState> pd;
  if (decider) pd.emplace(*decider);
  const int m = pixels.mode == Reconstruction::Splat ? pixels.splat_margin() : 0, side = kBlock + 2 * m;
  for (int k = k0; k < k1; ++k) {
    int bx, by;
    block_origin(region, k, &bx, &by);
    PixelRenderer p = pixels;
    p.ox = bx - m, p.oy = by - m;
    Film film(side, side), decide(decider ? side : 0, decider ? side : 0);
    for (int y = by; y < std::min(by + kBlock, region.y1); ++y)
      for (int x = bx; x < std::min(bx + kBlock, region.x1); ++x)
        p.run(x, y, 0, spp, film, decider ? &decide : nullptr, ps, pd ? &*pd : nullptr);
  }
}

// The ranks' wall seconds per sample combined: their rates add up.
double combined(double mine, const ProcessGroup& group) {
  std::vector<std::byte> bytes(sizeof mine);
  std::memcpy(bytes.data(), &mine, sizeof mine);
  double rate = 0;
  for (const std::vector<std::byte>& b : group.all_gather(bytes)) {
    double s;
    std::memcpy(&s, b.data(), sizeof s);
    rate += s > 0 ? 1 / s : 0;
  }
  return rate > 0 ? 1 / rate : 0;
}

}  // namespace

RenderEstimate estimate_render(const PixelRenderer& pixels, const Sampler& sampler, const Sampler* decider,
                               const PixelRect& region, int64_t spp, double samples, const ProcessGroup& group) {
  using clock = std::chrono::steady_clock;
  RenderEstimate e;
  e.samples = samples;
  const int64_t cal = std::min(spp, kCalibrationSpp);
  const int pixels_per_block = std::min(kBlock, region.width()) * std::min(kBlock, region.height());
  const auto run = [&](int k0, int k1) {
    tbb::parallel_for(tbb::blocked_range<int>(k0, k1), [&](const tbb::blocked_range<int>& r) {
      render_blocks(pixels, sampler, decider, region, r.begin(), r.end(), cal);
    });
  };
  // Untimed: the first touches of textures (loaded on demand) and caches, paid once per render.
  run(0, kWarmUpBlocks);
  // Blocks it may take: 4 at least, so that every render is timed.
  const double cap = std::max(4.0, samples * kCalibrationShare / double(pixels_per_block * cal));
  const auto t0 = clock::now();
  const double cpu0 = process_cpu_seconds();
  // Rounds of doubling size, the last one cut to what the time left allows at the rate so far.
  for (int n = 0, next = 4; next > n;) {
    run(kWarmUpBlocks + n, kWarmUpBlocks + next);
    e.calibration_pixels += (next - n) * pixels_per_block;
    n = next;
    e.calibration_seconds = std::chrono::duration<double>(clock::now() - t0).count();
    const double fit = (kCalibrationTime - e.calibration_seconds) / e.calibration_seconds * n;
    next = n + int(std::clamp(std::min(fit, cap - n), 0.0, double(n)));
  }
  e.calibration_cpu_seconds = process_cpu_seconds() - cpu0;
  e.calibration_samples = int64_t(e.calibration_pixels) * cal;
  e.seconds_per_sample = combined(e.calibration_seconds / double(e.calibration_samples), group);
  e.seconds = samples * e.seconds_per_sample;
  return e;
}

}  // namespace pdrt
