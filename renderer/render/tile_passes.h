#pragma once
// Passes over the image: in each, every pixel extends its prefix of samples to a count the
// caller chooses. A pass renders the tile waves in order, this rank's tiles of a wave in
// parallel (TBB), and exchanges the wave with the other ranks before the next; it stops early
// when the render is cancelled or its time limit is reached. The passes count the rays and
// samples this rank traced.
#include "renderer/render/pixel_renderer.h"
#include "renderer/render/render_films.h"
#include "renderer/render/renderer.h"
#include "renderer/render/thread_sampler_states.h"
#include "renderer/render/tile_waves.h"
#include "renderer/render/wave_exchange.h"

#include <tbb/enumerable_thread_specific.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>

namespace pdrt {

class Progress;

// Which ranks need every rank's tiles after a pass (TilePasses::run).
enum class FilmsTo { None, Everyone };

class TilePasses {
 public:
  // `decider`: the decision samples' sampler under "split", else nullptr; `start`: when the
  // render started (options.time_limit counts from it).
  TilePasses(const TileWaves& tiles, RenderFilms& films, const PixelRenderer& pixels, const Sampler& sampler,
             const Sampler* decider, const ProcessGroup& group, const RenderOptions& opt,
             std::chrono::steady_clock::time_point start);

  // Pixel (x, y) of the film (film coordinates) gets samples up to end_of(x, y); `progress`
  // advances by the budget samples each tile adds. False when the pass was stopped.
  // `to`: who reads the films after the pass. Everyone (adaptive decisions): every rank gets
  // every rank's tiles. None (the passes of a fixed-spp render; gather_image takes the image to
  // rank 0 at the end): without splatting (no footprint reaches another rank's tile) the ranks
  // only agree whether to stop, as each renders the same tiles in every pass, and the blocks
  // go only when one was stopped. Splatting shares every wave with everyone. Once every rank
  // holds the same films (after an exchange with everyone), an exchange carries only the tiles
  // that took samples since: an adaptive round sends the tiles it refines.
  bool run(const std::function<int64_t(int, int)>& end_of, Progress& progress, FilmsTo to = FilmsTo::Everyone);
  // The budget samples a pass to end_of would add to this rank's pixels (its progress's total).
  double work(const std::function<int64_t(int, int)>& end_of) const;
  // Renders blocks [b0, b1) of `blocks` (image pixels, each inside one of this rank's tiles,
  // no two alike) to `end` samples a pixel, in parallel, counted as the tiles' samples are: the
  // time estimate's calibration (render_estimate.h), whose samples are then the pixels' first.
  // Without splatting a pixel's samples go to it alone, in index order, so the image does not
  // depend on which pixels the calibration took; `end`, a pass's end (a block goes through the
  // passes in order), keeps every pass's image too. The films are no longer the same on every
  // rank: the next exchange sends every tile. Returns the seconds the threads spent inside the
  // blocks, summed. A block taken past the first pass is kept as it was before, for
  // restore_calibration.
  double calibrate(const std::vector<PixelRect>& blocks, std::size_t b0, std::size_t b1, int64_t end);
  // After a stop: the calibrated blocks that went past the pass every pixel of this rank's
  // tiles ended are put back as they were at its end, so that a render stopped between two
  // passes is the render of the spp reached, bit for bit.
  void restore_calibration();
  // Whether image pixel (x, y) lies in one of this rank's tiles.
  bool owns(int x, int y) const { return own_tile_[std::size_t(tiles_.tile_at(x, y))] != 0; }

  bool stopped() const { return stopped_; }  // some pass was stopped
  // Cancelled (RenderOptions::cancel), or past the time limit.
  bool interrupted() const {
    return (opt_.cancel && opt_.cancel->load(std::memory_order_relaxed)) ||
           (opt_.time_limit > 0 && std::chrono::steady_clock::now() >= deadline_);
  }
  // This rank's counts so far: tiles, exchanges, rays and samples traced.
  RankStats rank_stats() const;

 private:
  // Returns the budget samples it added.
  int64_t render_tile(int t, const std::function<int64_t(int, int)>& end_of, std::atomic<bool>& cancelled);
  // The same for any rectangle of image pixels.
  int64_t render_pixels(const PixelRect& p, const std::function<int64_t(int, int)>& end_of,
                        std::atomic<bool>& cancelled);
  // Maps the films' pages under this rank's tiles' footprints writable, in parallel, before any
  // pass reads them (Film::populate): the others' pages stay unmapped until an exchange writes them.
  void populate_own_tiles();
  // This rank's tiles of `wave` (positions in it; rank_tiles).
  std::vector<std::size_t> own_tiles(const std::vector<int>& wave) const;
  // Image pixel (x, y)'s accumulator.
  const PixelAccum& pixel(int x, int y) const {
    return films_.image.at(x - tiles_.region().x0, y - tiles_.region().y0);
  }
  // A calibration block's accumulators, in both films, at the pass end `end` (their prefix).
  struct BlockSnapshot {
    PixelRect rect;
    int64_t end = 0;
    std::vector<PixelAccum> image, decision;
  };
  BlockSnapshot snapshot(const PixelRect& b);
  // f(image, decision) for each pixel of image rectangle b, row by row (decision: null unless split).
  template <class F>
  void each_accum(const PixelRect& b, F&& f) {
    const PixelRect& region = tiles_.region();
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0; x < b.x1; ++x)
        f(films_.image.at(x - region.x0, y - region.y0),
          films_.split ? &films_.decision.at(x - region.x0, y - region.y0) : nullptr);
  }

  const TileWaves& tiles_;
  RenderFilms& films_;
  const PixelRenderer& pixels_;
  ThreadSamplerStates states_;
  const ProcessGroup& group_;
  const RenderOptions& opt_;
  WaveExchange exchange_;
  // Under mpirun a SIGKILL follows the SIGTERM within a second (docs/distributed.md): a
  // distributed render stops at the next pixel, not after the tile, so the partial image gets out.
  bool stop_in_tile_;
  std::chrono::steady_clock::time_point deadline_;  // RenderOptions::time_limit after the start
  tbb::enumerable_thread_specific<int64_t> rays_{0}, traced_{0};
  tbb::enumerable_thread_specific<double> busy_{0.0};  // seconds inside render_tile
  RankStats mine_;
  bool stopped_ = false;
  // Every rank holds the same films (all zero at the start; after an exchange with everyone).
  bool in_step_ = true;
  std::vector<uint8_t> own_tile_;  // by tile index: this rank renders it
  // By tile index: some pixel of it may hold samples (a calibration block lies in it, or a pass
  // ran). work() reads the others' prefixes as 0 instead of from the films, whose pixels are
  // 224 bytes apart: reading them all, twice before the first pass, cost bench_render 7-17 %
  // even once Film::populate had touched the pages.
  std::vector<uint8_t> sampled_;
  std::vector<BlockSnapshot> snapshots_;  // the calibration's blocks before each pass past the first
};

}  // namespace pdrt
