#pragma once
// A render's statistics (RenderStats): its clocks, every rank's share gathered on every rank,
// and the counts over the films.
#include "renderer/render/process_group.h"
#include "renderer/render/render_films.h"
#include "renderer/render/render_region.h"
#include "renderer/render/renderer.h"

#include <chrono>
#include <cstdint>

namespace pdrt {

// Wall and process CPU time of a render, and of its scene build (Embree BVH, lights, camera).
class RenderClock {
 public:
  RenderClock();      // starts both clocks
  void build_done();  // the scene is built: the rest is rendering
  double build_seconds() const { return build_seconds_; }
  std::chrono::steady_clock::time_point start() const { return t0_; }
  // Fills seconds, build_seconds, cpu_seconds and build_cpu_seconds: the times until now.
  void finish(RenderStats& stats) const;

 private:
  std::chrono::steady_clock::time_point t0_;
  double cpu0_ = 0, build_seconds_ = 0, build_cpu_seconds_ = 0;
};

// Collective when distributed: every rank's stats on every rank, by rank (integers: exact).
std::vector<RankStats> gather_rank_stats(const RankStats& mine, const ProcessGroup& group);

// What the films' pixels say of the samples: traced (the margin's too: work done), dropped,
// and in the crop the sum (for its mean spp: the margin's samples are not the image's spp) and
// the spp all its pixels reached. Integers: the same however the pixels are split and summed.
struct SampleCounts {
  int64_t samples = 0, dropped = 0, crop_samples = 0, crop_complete = INT64_MAX;
  SampleCounts& operator+=(const SampleCounts& o);
};
// Over image pixels `r` of the rendered rectangle, rows in parallel.
SampleCounts count_pixels(const RenderFilms& films, const RenderRegion& region, const PixelRect& r);

// Fills the stats from the ranks (the rays) and the counts over every pixel.
void count_samples(const SampleCounts& counts, const RenderRegion& region, RenderStats& stats);

// Warns (unless `quiet`) when samples were dropped for a NaN or infinite value.
void warn_nonfinite(const RenderStats& stats, bool quiet);

// The worker threads a render runs on: the arena's size capped by the global limit (set by
// render() when options.threads > 0, or by a caller).
int worker_threads();

}  // namespace pdrt
