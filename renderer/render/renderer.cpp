#include "renderer/render/renderer.h"

#include "renderer/render/adaptive_rounds.h"
#include "renderer/render/cpu_affinity.h"
#include "renderer/render/embree_scene.h"
#include "renderer/render/filter.h"
#include "renderer/render/image_gather.h"
#include "renderer/render/light_set.h"
#include "renderer/render/path_integrator.h"
#include "renderer/render/pixel_renderer.h"
#include "renderer/render/progressive_passes.h"
#include "renderer/render/render_films.h"
#include "renderer/render/render_region.h"
#include "renderer/render/render_statistics.h"
#include "renderer/render/thin_lens_camera.h"
#include "renderer/render/tile_passes.h"
#include "renderer/render/tile_waves.h"
#include "renderer/render/warning_relay.h"
#include "renderer/scene/render_settings.h"
#include "sampling/core/errors.h"
#include "sampling/core/progress.h"

#include <tbb/global_control.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>

namespace pdrt {

std::unique_ptr<Sampler> make_scene_sampler(const SamplerDesc& d, const FilmDesc& film) {
  const SamplerShape shape{d.adaptive.enabled ? d.adaptive.min_spp : d.spp, film.width, film.height};
  return make_sampler(d.type, d.seed, shape);
}

void check_film_memory(int width, int height, const std::string& where, int films) {
  double need = double(width) * double(height) * double(Film::kBytesPerPixel) * films;
  double have = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (need > 0.75 * have) {
    char buf[200];
    std::snprintf(buf, sizeof buf, ": film %dx%d needs %.1f GiB of buffers; this machine has %.1f GiB", width, height,
                  need / (1 << 30), have / (1 << 30));
    throw InputError(where + buf);
  }
}

// The pipeline: the region to render (crop window and its margins), the scene build, the
// passes over the tile waves (one, or adaptive rounds), then the image and the statistics
// gathered over the ranks, with their warnings.
RenderResult render(const SceneDesc& desc, const Sampler& sampler, const RenderOptions& opt) {
  const AdaptiveDesc& ad = desc.sampler.adaptive;
  check_render_settings(desc);
  const bool split = ad.enabled && ad.decision == AdaptiveDecision::Split;
  const RenderRegion region = render_region(desc);
  check_film_memory(region.rect.width(), region.rect.height(), desc.film.size_where, split ? 2 : 1);
  warn_thread_request(opt.threads);
  std::optional<tbb::global_control> limit;
  if (opt.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(opt.threads));
  RenderClock clock;

  EmbreeDevice device(opt.threads > 0 ? "threads=" + std::to_string(opt.threads) : "");
  EmbreeScene scene(desc, device);
  const int footprint_spp = desc.sampler.adaptive.enabled ? desc.sampler.adaptive.max_spp : desc.sampler.spp;
  MaterialSet materials(scene, TextureFootprint(desc.camera, desc.film.width, desc.film.height, footprint_spp),
                        desc.integrator.regularize);
  LightSet lights(scene, materials.textures());
  PathIntegrator integrator(scene, lights, materials, desc.integrator);
  ThinLensCamera camera(desc.camera, desc.film.width, desc.film.height);
  Filter filter(desc.film.filter);
  RenderFilms films(region.rect.width(), region.rect.height(), split);
  const std::unique_ptr<Sampler> decider = split ? make_decision_sampler(desc.sampler, desc.film, sampler) : nullptr;
  std::optional<ExpectedSplatWeight> expected;
  if (sampler.pixel_counts_vary() && desc.film.filter.reconstruction == Reconstruction::Splat)
    expected.emplace(filter, desc.film.width, desc.film.height);
  const PixelRenderer pixels{camera,
                             scene,
                             integrator,
                             filter,
                             desc.film.filter.reconstruction,
                             region.rect.x0,
                             region.rect.y0,
                             expected ? &*expected : nullptr,
                             has_motion(desc)};
  clock.build_done();

  const LocalProcessGroup alone;
  const ProcessGroup& group = opt.group ? *opt.group : alone;
  RenderResult res;
  const int64_t spp = ad.enabled ? ad.max_spp : desc.sampler.spp;
  const bool splat = desc.film.filter.reconstruction == Reconstruction::Splat;
  const TileWaves tiles(desc.film.width, desc.film.height, region.rect, splat ? pixels.splat_margin() : 0);
  TilePasses passes(tiles, films, pixels, sampler, decider.get(), group, opt, clock.start());
  if (opt.on_estimate) {
    // The calibrated pixels take the first passes, kept in the film unless splatted (render_estimate.h).
    const bool kept = !splat;
    const std::vector<PixelRect> blocks = calibration_blocks(
        region.rect, kept, [&](int x, int y) { return passes.owns(x, y); }, 1 << 16);
    const CalibrationRender calibrate = [&](std::size_t b0, std::size_t b1, int64_t n) {
      return kept ? passes.calibrate(blocks, b0, b1, n)
                  : render_scratch_blocks(pixels, sampler, decider.get(), blocks, b0, b1, n);
    };
    EstimatePlan plan{{},
                      double(region.rect.width()) * region.rect.height() * double(spp),
                      kept,
                      worker_threads(),
                      pass_count(spp) * int(tiles.waves().size())};
    for (int64_t e = 0, round0 = ad.enabled ? ad.min_spp : spp; e < round0 && (kept || e == 0);)
      plan.ends.push_back(e = next_pass_end(e, round0));
    res.stats.estimate = estimate_render(blocks, plan, calibrate, group);
    opt.on_estimate(res.stats.estimate);
  }
  const bool quiet = opt.quiet || group.rank() != 0;
  const auto p0 = std::chrono::steady_clock::now();
  int rounds = 0;
  SamplerProfiler profiler;  // the passes only: the build and the image are not sampling work
  if (ad.enabled) {
    rounds = render_adaptive_rounds(ad, region, films, passes, quiet, opt.on_pass);
  } else {
    Progress progress("render", passes.work([spp](int, int) { return spp; }), quiet);
    // The ETA is the estimate's until the first pass whose samples spread over the frame is
    // done: the calibration's last, which it took on some of the blocks only (the passes
    // before it, it took whole).
    int64_t first = next_pass_end(0, spp);
    for (int k = 1; k < res.stats.estimate.calibration_passes && first < spp; ++k) first = next_pass_end(first, spp);
    progress.expect(res.stats.estimate.seconds, passes.work([first](int, int) { return first; }));
    // No rank reads the others' tiles after the last pass: gather_image takes the image to rank 0.
    render_progressive(passes, spp, progress, opt.on_pass, FilmsTo::None);
  }
  if (passes.stopped()) passes.restore_calibration();
  res.stats.passes_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - p0).count();
  res.stats.sampler_profile = profiler.result();
  device.check();
  RankStats mine = passes.rank_stats();
  GatheredImage gathered = gather_image(films, tiles, region, desc.film.exposure, group, mine);
  res.image = std::move(gathered.image);
  clock.finish(res.stats);
  mine.seconds = res.stats.seconds - clock.build_seconds();
  res.stats.ranks = gather_rank_stats(mine, group);
  if (group.size() > 1) relay_held_warnings(group);
  count_samples(gathered.counts, region, res.stats);
  warn_adaptive_crop(desc, region, rounds, opt.quiet);
  warn_nonfinite(res.stats, opt.quiet);
  res.stats.partial = passes.stopped();
  res.stats.adaptive_rounds = rounds;
  res.stats.triangles = scene.triangle_count();
  res.stats.threads = worker_threads();
  res.stats.cpus_allowed = allowed_cpus();
  return res;
}

}  // namespace pdrt
