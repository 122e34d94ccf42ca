#pragma once
// The passes of a render at a fixed spp: every pass covers the whole frame, so a render stopped
// between passes (Ctrl-C, SIGTERM under mpirun, --time-limit) holds a complete image at the spp
// every pixel reached, not finished strips next to black ones. As pbrt-v4's waves
// (gpu/integrator.cpp) the pass sizes double, so the spp after each pass is 8, 16, 32, 64, ...,
// a power of two up to the last pass (the stratified samplers' prefixes are best there). Two
// differences, both for cost: the first pass is 8, not 1: camera rays go to Embree in packets of
// the samples [4j, 4j + 4) (pixel_renderer.h), a pass ending inside a packet traces its camera
// rays twice, and a pixel's pass has a fixed cost (it prepares each of its sample streams anew,
// PixelSampleState::set_pixel_pass); 8 is also what the time estimate's calibration renders a
// pixel to, so its samples are the first pass's and stay in the film (render_estimate.h). And
// the sizes are not capped at pbrt-v4's 64: that fixed cost, doubling passes pay log2(spp)
// times per pixel, capped ones spp / 64 times.
#include <cstdint>
#include <functional>

namespace pdrt {

inline constexpr int64_t kFirstPassSpp = 8;

// The spp every pixel has after the pass that starts at `done` of a `spp` render (done < spp).
inline int64_t next_pass_end(int64_t done, int64_t spp) {
  if (done <= 0) return spp < kFirstPassSpp ? spp : kFirstPassSpp;
  return spp - done < done ? spp : 2 * done;
}

// How many passes a `spp` render takes.
inline int pass_count(int64_t spp) {
  int n = 0;
  for (int64_t done = 0; done < spp; done = next_pass_end(done, spp)) ++n;
  return n;
}

class Progress;
class TilePasses;
enum class FilmsTo;

// Renders every pixel from 0 to `spp` samples in those passes, on `progress` (the whole render's
// work: budget samples of this rank's pixels); calls `on_pass` (if set) with the spp after each
// complete pass. Returns the spp every pixel reached: `spp`, or less when a pass was stopped.
// `last`: the ranks that read the films after the last pass (tile_passes.h).
int64_t render_progressive(TilePasses& passes, int64_t spp, Progress& progress,
                           const std::function<void(int64_t)>& on_pass, FilmsTo last);

}  // namespace pdrt
