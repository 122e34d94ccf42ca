#pragma once
// Passes over the image: in each, every pixel extends its prefix of samples to a count the
// caller chooses. A pass renders the tile waves in order, this rank's tiles of a wave in
// parallel (TBB), and exchanges the wave with the other ranks before the next; it stops early
// when the render is cancelled. The passes count the rays and samples this rank traced.
#include "renderer/render/pixel_renderer.h"
#include "renderer/render/render_films.h"
#include "renderer/render/renderer.h"
#include "renderer/render/tile_waves.h"
#include "renderer/render/wave_exchange.h"

#include <tbb/enumerable_thread_specific.h>

#include <atomic>
#include <cstdint>
#include <functional>

namespace pdrt {

class TilePasses {
 public:
  // `decider`: the decision samples' sampler under "split", else nullptr.
  TilePasses(const TileWaves& tiles, RenderFilms& films, const PixelRenderer& pixels, const Sampler& sampler,
             const Sampler* decider, const ProcessGroup& group, const RenderOptions& opt);

  // Pixel (x, y) of the film (film coordinates) gets samples up to end_of(x, y). `label`
  // names the pass on the progress bar. False when the pass was cancelled.
  bool run(const char* label, const std::function<int64_t(int, int)>& end_of);

  bool stopped() const { return stopped_; }  // some pass was cancelled
  // This rank's counts so far: tiles, exchanges, rays and samples traced.
  RankStats rank_stats() const;

 private:
  void render_tile(int t, const std::function<int64_t(int, int)>& end_of, std::atomic<bool>& cancelled);

  const TileWaves& tiles_;
  RenderFilms& films_;
  const PixelRenderer& pixels_;
  const Sampler& sampler_;
  const Sampler* decider_;
  const ProcessGroup& group_;
  const RenderOptions& opt_;
  WaveExchange exchange_;
  // Under mpirun a SIGKILL follows the SIGTERM within a second (docs/distributed.md): a
  // distributed render stops at the next pixel, not after the tile, so the partial image gets out.
  bool stop_in_tile_;
  tbb::enumerable_thread_specific<int64_t> rays_{0}, traced_{0};
  tbb::enumerable_thread_specific<double> busy_{0.0};  // seconds inside render_tile
  RankStats mine_;
  bool stopped_ = false;
};

}  // namespace pdrt
