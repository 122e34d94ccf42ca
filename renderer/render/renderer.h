#pragma once
// Renders a scene: TBB over 16x16 tiles, each pixel's samples drawn from the replayable
// sampler in index order, so the image is bit-identical for a seed at any thread count.
#include "renderer/render/embree_device.h"
#include "renderer/render/film.h"
#include "renderer/render/process_group.h"
#include "renderer/render/render_estimate.h"
#include "sampling/samplers/sampler.h"
#include "renderer/scene/scene_desc.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace pdrt {

struct RenderOptions {
  int threads = 0;                            // 0 = every CPU of the affinity mask (TBB's default)
  bool quiet = false;                         // no progress on stderr
  const std::atomic<bool>* cancel = nullptr;  // set (e.g. by SIGINT) to stop early
  // The processes sharing the render (docs/distributed.md); nullptr = this one alone. Rank 0
  // returns the single process's image, bit for bit; the others an empty image (they hold only
  // their own tiles). Every rank has the same statistics.
  const ProcessGroup* group = nullptr;
  // > 0: stop this many seconds after render() starts (scene build included), as a cancel
  // would; the passes (progressive_passes.h) leave every pixel at some spp.
  double time_limit = 0;
  // Set: the render is calibrated after the scene build (render_estimate.h) and this is called
  // with the estimate before any pass (on every rank, with the same estimate). It may throw to
  // refuse the render (the sample budget).
  std::function<void(const RenderEstimate&)> on_estimate;
  // Called after each complete pass (of a fixed-spp render, or of adaptive round 0) with the spp
  // every pixel has then.
  std::function<void(int64_t)> on_pass;
};

// One process's share of a distributed render.
struct RankStats {
  int rank = 0;
  double seconds = 0;           // rendering, after the scene build (exchanges included)
  double exchange_seconds = 0;  // of that, waiting for and copying the other ranks' blocks
  int64_t samples = 0;          // camera samples this rank traced
  int64_t rays = 0;
  int64_t tiles = 0;       // tile passes it rendered
  int64_t bytes_sent = 0;  // its blocks' pixel state, sent to every other rank
  // Thread-seconds its workers spent inside tiles: over threads x (seconds - exchange_seconds),
  // the share of the workers' time that was work, the rest waiting (end of a wave, idle threads).
  double tile_seconds = 0;
};

struct RenderStats {
  double seconds = 0;             // total: scene build + rendering
  double build_seconds = 0;       // Embree BVH build, lights, camera
  double cpu_seconds = 0;         // process CPU time (user + sys, all threads) over the whole render
  double build_cpu_seconds = 0;   // of that, the build's
  int64_t rays = 0;               // extension + shadow rays
  int64_t samples = 0;            // camera samples traced
  int64_t nonfinite_samples = 0;  // of those, dropped for a NaN or infinite value
  double spp_mean = 0;
  int64_t spp_complete = 0;   // the spp every pixel of the crop reached (its budget: less than spp_mean when partial)
  bool partial = false;       // stopped before every pixel was done
  RenderEstimate estimate;    // when options.on_estimate is set
  double passes_seconds = 0;  // the passes' wall time (after the build and the calibration)
  int adaptive_rounds = 0;    // refinement rounds after the first pass
  std::size_t triangles = 0;
  int threads = 0;                 // worker threads the render ran on (options' 0 resolved)
  int cpus_allowed = 0;            // CPUs in the process's affinity mask (renderer/render/cpu_affinity.h)
  SamplerProfile sampler_profile;  // CPU ticks of the passes, and those spent computing sample values
  std::vector<RankStats> ranks;    // per process, by rank (one entry when not distributed)
};

struct RenderResult {
  Image image;
  RenderStats stats;
};

// The sampler the scene (after command-line overrides) asks for; `film` gives the samplers that
// arrange samples across pixels (zsobol) the image and the first pass's samples per pixel.
std::unique_ptr<Sampler> make_scene_sampler(const SamplerDesc& d, const FilmDesc& film);

// Refuses (InputError) a film whose buffers would not fit in this machine's memory; the
// message starts with `where` (the scene's film.width location, or the options that set it).
// `films`: 2 when adaptive decision "split" keeps a second film of decision samples.
void check_film_memory(int width, int height, const std::string& where = "film", int films = 1);

RenderResult render(const SceneDesc& scene, const Sampler& sampler, const RenderOptions& options);

}  // namespace pdrt
