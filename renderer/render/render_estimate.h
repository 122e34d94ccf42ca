#pragma once
// What a render will cost on this machine and this scene (issue 33), said before it starts and
// used by the sample budget: after the scene build, blocks of 4x4 pixels scattered over the
// frame (the R2 sequence, Roberts 2018: any prefix of it is spread evenly) are rendered on the
// render's threads: 8 blocks untimed (caches warm on first use), then for 0.1 s (splatting:
// 0.05 s) or half the render's samples, each pixel to the first pass's end (min(spp, 8),
// progressive_passes.h) and, while time is left after every block, through the next passes (so
// a cheap scene is timed for as long, and on passes that share a pixel's fixed cost among more
// samples). The rate is the threads' busy time per sample over the threads; the estimate is
// that times the samples the passes will take, plus, for each of the passes' parallel loops,
// the time the calibration's largest round had threads waiting. It must run for tens of milliseconds on a
// busy machine: a shorter burst gets whole cores that the render then shares. The blocks'
// samples are the pixels' first passes, kept in the film (TilePasses::calibrate), so the
// calibration costs the render nothing; when splatting they go to scratch films, thrown away:
// a splatted sample reaches neighbouring pixels, whose order of contributions the calibration
// would change. (With a first pass of 4, blocks of 4 samples a pixel estimated 256-spp renders
// at up to 2.5x their time: a pixel's pass has a fixed cost, which 4 samples share less than
// 8.) Measured against the actual passes by tools/estimate-accuracy.sh (docs/renderer.md,
// "Estimates").
#include "renderer/render/process_group.h"
#include "renderer/scene/crop_window.h"
#include "sampling/samplers/sampler.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace pdrt {

struct PixelRenderer;

struct RenderEstimate {
  double samples = 0;                  // the render's camera samples (budget; the most, under adaptive)
  double seconds_per_sample = 0;       // wall time, every thread and every rank together
  double loop_seconds = 0;             // and per parallel loop of the passes (threads waiting)
  int loops = 0;                       // the passes' parallel loops
  double seconds = 0;                  // the passes': samples not yet taken x seconds_per_sample + loops x loop_seconds
  double calibration_seconds = 0;      // wall time the calibration took on this rank
  double calibration_cpu_seconds = 0;  // its process CPU time (to tell the method's error from the load's)
  double calibration_busy_seconds = 0;  // the threads' wall time inside its blocks, summed
  int64_t calibration_samples = 0;
  int calibration_pixels = 0;
  int calibration_passes = 0;     // the passes it took its pixels through (the later on fewer pixels)
  bool calibration_kept = false;  // its samples are the pixels' first (else thrown away, when splatting)
};

// The calibration's blocks of 4 x 4 pixels cut by `region`, at most `most`, in the order of the
// R2 sequence. Kept in the film: aligned to multiples of 4 in image coordinates (so a block
// lies in one tile), each once, those whose top-left pixel `mine` accepts (under mpirun, this
// rank's tiles). Else anywhere, overlapping as they fall (as the estimate was measured).
std::vector<PixelRect> calibration_blocks(const PixelRect& region, bool kept, const std::function<bool(int, int)>& mine,
                                          std::size_t most);

// Renders blocks [b0, b1) of the calibration's to `spp` samples a pixel, on the render's threads;
// returns the seconds the threads spent inside the blocks, summed.
using CalibrationRender = std::function<double(std::size_t b0, std::size_t b1, int64_t spp)>;

struct EstimatePlan {
  // The pass ends a calibrated pixel may be rendered to, in order: the first pass's end, and
  // when the blocks are kept, the later passes' up to the render's first round (the passes
  // then skip what the calibration took: the pixels' samples and pass boundaries stay).
  std::vector<int64_t> ends;
  double samples = 0;  // the render's total
  bool kept = false;   // the blocks' samples stay in the film (the passes then take the rest)
  int threads = 1;     // the render's
  int loops = 0;       // the passes' parallel loops (passes x tile waves)
};

// Collective when distributed: every rank gets the same estimate (the ranks' rates summed).
RenderEstimate estimate_render(const std::vector<PixelRect>& blocks, const EstimatePlan& plan,
                               const CalibrationRender& render, const ProcessGroup& group);

// Renders blocks [b0, b1) into films of their own, with the splats' margin, that are thrown
// away; `decider`: the decision samples' sampler under "split", else nullptr. Returns the
// seconds the threads spent inside them, summed.
double render_scratch_blocks(const PixelRenderer& pixels, const Sampler& sampler, const Sampler* decider,
                             const std::vector<PixelRect>& blocks, std::size_t b0, std::size_t b1, int64_t spp);

}  // namespace pdrt
