#pragma once
// What a render will cost on this machine and this scene (issue 33), said before it starts and
// used by the sample budget: after the scene build, blocks of 4x4 pixels scattered over the
// frame (the R2 sequence, Roberts 2018: any prefix of it is spread evenly) are rendered into a
// scratch film, on the render's threads: 8 blocks untimed (textures load on first use), then
// for 0.05 s or half the render's samples (at most 8 per pixel); their wall time per sample
// times the render's samples is the estimate. It must run for tens of milliseconds on a busy
// machine: a shorter burst gets whole cores that the render then shares. The scratch film is thrown
// away, so the image does not change. Measured against the actual passes by
// tools/estimate-accuracy.sh (docs/renderer.md, "Estimates").
#include "renderer/render/process_group.h"
#include "renderer/scene/crop_window.h"
#include "sampling/samplers/sampler.h"

#include <cstdint>

namespace pdrt {

struct PixelRenderer;

struct RenderEstimate {
  double samples = 0;                  // the render's camera samples (budget; the most, under adaptive)
  double seconds_per_sample = 0;       // wall time, every thread and every rank together
  double seconds = 0;                  // samples x seconds_per_sample: the passes after the calibration
  double calibration_seconds = 0;      // wall time the calibration took on this rank
  double calibration_cpu_seconds = 0;  // its process CPU time (to tell the method's error from the load's)
  int64_t calibration_samples = 0;
  int calibration_pixels = 0;
};

// `region`: the rendered rectangle (image pixels); `spp`: the pixels' budget (max_spp when
// adaptive); `samples`: the render's total; `decider`: under "split" decisions, else nullptr.
// Collective when distributed: every rank gets the same estimate (the ranks' rates summed).
RenderEstimate estimate_render(const PixelRenderer& pixels, const Sampler& sampler, const Sampler* decider,
                               const PixelRect& region, int64_t spp, double samples, const ProcessGroup& group);

}  // namespace pdrt
