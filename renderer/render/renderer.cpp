#include "renderer/render/renderer.h"

#include "renderer/render/adaptive_metric.h"
#include "renderer/render/camera_sample.h"
#include "renderer/render/embree_scene.h"
#include "sampling/core/errors.h"
#include "renderer/render/filter.h"
#include "renderer/render/light_sampler.h"
#include "renderer/render/path_integrator.h"
#include "renderer/render/process_cpu_time.h"
#include "sampling/core/progress.h"
#include "sampling/core/rng.h"
#include "sampling/core/warnings.h"
#include "renderer/render/thin_lens_camera.h"
#include "renderer/scene/crop_window.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <optional>

namespace pdrt {

std::unique_ptr<Sampler> make_scene_sampler(const SamplerDesc& d) { return make_sampler(d.type, d.seed); }

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

namespace {

constexpr int kTile = 16;

struct PixelRenderer {
  const ThinLensCamera& camera;
  const EmbreeScene& scene;
  const PathIntegrator& integrator;
  const Filter& filter;
  Reconstruction mode;
  int ox = 0, oy = 0;  // the film's pixel (0, 0) in image pixels (crop window)

  // Pixels beyond its own that a splatted sample can reach (film point in [x, x + 1)).
  int splat_margin() const { return int(std::ceil(filter.radius())) + 1; }

  // Samples [begin, end) of pixel (x, y) into `film`; returns rays traced. Camera rays go to
  // Embree as packets of four: always the samples [4j, 4j + 4), whatever [begin, end) is,
  // because packet and single-ray kernels may differ in the last bit; so a pixel's samples
  // are the same whether it is rendered at once or over adaptive rounds.
  // With `decide` (decision "split"), odd i go there and even i to `film`, as sample i >> 1
  // of two independent samplers (`pd` for the decision, seeded apart): each film gets a full
  // prefix of its own sampler, stratified as a whole, and the estimate's samples are
  // independent of the ones that chose when to stop. Each film's `halves` buffers split it by
  // the parity of i >> 1.
  // Under rank selection [begin, end) is a budget: every candidate of the larger prefix is
  // visited, and those kept now but not before are traced.
  int64_t run(int x, int y, int64_t begin, int64_t end, Film& film, Film* decide, PixelSampleState& ps,
              PixelSampleState* pd) const {
    CameraSampleRule rule{filter, mode};
    int64_t first = begin & ~int64_t(3), last = end;
    if (mode == Reconstruction::Rank) {
      rule.rank_candidates = rank_candidates(filter, end);
      rule.rank_candidates_before = begin > 0 ? rank_candidates(filter, begin) : 0.0;
      first = 0, last = int64_t(std::ceil(rule.rank_candidates));
    }
    const int64_t from = decide ? first / 2 : first, to = decide ? (last + 1) / 2 : last;  // each stream's indices
    ps.set_pixel_pass(from, to);
    if (pd) pd->set_pixel_pass(from, to);
    int64_t rays = 0;
    for (int64_t g = first; g < last; g += 4) {
      Ray ray[4];
      CameraSample cs[4];
      bool live[4], found[4];
      SurfaceHit hit[4];
      auto stream = [&](int64_t i) -> PixelSampleState& { return decide && (i & 1) ? *pd : ps; };
      auto index = [&](int64_t i) { return decide ? i >> 1 : i; };
      for (int k = 0; k < 4; ++k) {
        live[k] = get_camera_sample(rule, x, y, index(g + k), stream(g + k), &cs[k]);
        if (live[k]) ray[k] = camera.generate(cs[k].film_x, cs[k].film_y, cs[k].lens, cs[k].time);
      }
      if (!(live[0] || live[1] || live[2] || live[3])) continue;
      scene.intersect4(ray, live, hit, found);
      for (int k = 0; k < 4; ++k) {
        const int64_t i = g + k;
        if (!live[k]) continue;
        if (mode != Reconstruction::Rank && (i < begin || i >= end)) {
          ++rays;  // traced for the packet's sake only
          continue;
        }
        PixelSampleState& st = stream(i);
        st.start_pixel_sample(x, y, index(i));
        PathResult pr = integrator.trace(ray[k], st, hit[k], found[k]);
        rays += pr.rays;
        Film& dst = decide && (i & 1) ? *decide : film;
        const int half = int(index(i) & 1);
        PixelAccum& own = dst.at(x - ox, y - oy);
        ++own.traced;
        if (mode != Reconstruction::Splat) {
          own.add(pr.radiance, cs[k].weight, pr.albedo, pr.normal, pr.depth, half);  // drops NaN / inf
        } else if (!is_finite(pr.radiance)) {
          ++own.dropped;  // once, not in every pixel it would have reached
        } else {
          splat(dst, cs[k].film_x, cs[k].film_y, pr, half);
        }
      }
    }
    film.at(x - ox, y - oy).prefix = end;
    if (mode == Reconstruction::Rank) film.at(x - ox, y - oy).norm = rule.rank_candidates * filter.mean_value();
    return rays;
  }

  // Cook §4.2: the sample at film point (fx, fy) adds to every pixel whose filter covers it
  // (of those the film holds: under a crop window, none beyond the rendered rectangle).
  void splat(Film& film, float fx, float fy, const PathResult& pr, int half) const {
    const float r = filter.radius();
    const int x0 = std::max(ox, int(std::ceil(fx - 0.5f - r))), x1 = std::min(ox + film.width() - 1, int(std::floor(fx - 0.5f + r)));
    const int y0 = std::max(oy, int(std::ceil(fy - 0.5f - r))), y1 = std::min(oy + film.height() - 1, int(std::floor(fy - 0.5f + r)));
    for (int qy = y0; qy <= y1; ++qy)
      for (int qx = x0; qx <= x1; ++qx) {
        const float w = filter.eval(fx - (float(qx) + 0.5f), fy - (float(qy) + 0.5f));
        if (w != 0) film.at(qx - ox, qy - oy).add(pr.radiance, w, pr.albedo, pr.normal, pr.depth, half);
      }
  }
};

}  // namespace

RenderResult render(const SceneDesc& desc, const Sampler& sampler, const RenderOptions& opt) {
  const AdaptiveDesc& ad = desc.sampler.adaptive;
  const bool split = ad.enabled && ad.decision == "split";
  if (split && desc.film.filter.reconstruction == Reconstruction::Rank)
    throw InputError("adaptive decision \"split\" needs reconstruction \"importance\" or \"splat\", not \"rank\"");
  const int W = desc.film.width, H = desc.film.height;
  const Reconstruction mode = desc.film.filter.reconstruction;
  // pbrt-v4 §5.4.2 crop window: only `crop` is output, but the pixels that can change it are
  // rendered too (docs/renderer.md, "Crop window"): a splatted sample reaches splat_margin
  // pixels, and each adaptive round lets a pixel's neighbours decide it refines.
  const PixelRect crop = crop_pixels(desc.film.crop_window, W, H);
  if (crop.empty())
    throw InputError(desc.film.size_where + ": film.crop_window covers no pixel of the " + std::to_string(W) + "x" +
                     std::to_string(H) + " film");
  const int reach = mode == Reconstruction::Splat ? int(std::ceil(desc.film.filter.radius)) + 1 : 0;
  int margin = reach, margin_rounds = 0;
  if (ad.enabled) {
    for (int64_t p = ad.min_spp; p < ad.max_spp; p *= 2) ++margin_rounds;
    margin = reach + ++margin_rounds * (1 + reach);
  }
  const bool metric_needs_mean = ad.enabled && AdaptiveMetric(ad).needs_image_mean();
  const PixelRect region{std::max(0, crop.x0 - margin), std::min(W, crop.x1 + margin), std::max(0, crop.y0 - margin),
                         std::min(H, crop.y1 + margin)};
  check_film_memory(region.width(), region.height(), desc.film.size_where, split ? 2 : 1);
  std::optional<tbb::global_control> limit;
  if (opt.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(opt.threads));
  auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_seconds();

  EmbreeDevice device(opt.threads > 0 ? "threads=" + std::to_string(opt.threads) : "");
  EmbreeScene scene(desc, device);
  const int footprint_spp = desc.sampler.adaptive.enabled ? desc.sampler.adaptive.max_spp : desc.sampler.spp;
  MaterialSet materials(scene, TextureFootprint(desc.camera, desc.film.width, desc.film.height, footprint_spp),
                        desc.integrator.regularize);
  LightSampler lights(scene, materials.textures());
  PathIntegrator integrator(scene, lights, materials, desc.integrator);
  ThinLensCamera camera(desc.camera, desc.film.width, desc.film.height);
  Filter filter(desc.film.filter);
  Film film(region.width(), region.height());  // pixel (x, y) of the image is film.at(x - region.x0, y - region.y0)
  // Kirk & Arvo (1991): samples that chose when a pixel stops bias its estimate, so with
  // "split" they are kept apart from the image and only decide.
  Film decision(split ? region.width() : 0, split ? region.height() : 0);
  std::unique_ptr<Sampler> decider;
  if (split) {
    SamplerDesc d = desc.sampler;
    d.type = sampler.name(), d.seed = mix64(sampler.seed() ^ 0x6465636964657273ull);  // "deciders"
    decider = make_scene_sampler(d);
  }
  const Film& judged = split ? decision : film;
  PixelRenderer pr{camera, scene, integrator, filter, mode, region.x0, region.y0};

  const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double build_cpu_seconds = process_cpu_seconds() - cpu0;
  const int tx = (W + kTile - 1) / kTile, ty = (H + kTile - 1) / kTile;
  tbb::enumerable_thread_specific<int64_t> rays(0);
  bool stopped = false;

  // Splatting writes into neighbouring tiles, so tiles run in waves whose footprints (tile
  // plus margin) are disjoint: no locks, and every pixel receives its contributions in the
  // same order at any thread count (wave order, then the tile's pixel order). Tiles and waves
  // are the full image's under a crop window too, so a pixel's contributions come in the same
  // order as in the full render.
  const int period = mode == Reconstruction::Splat ? 1 + (2 * pr.splat_margin() + kTile - 1) / kTile : 1;
  std::vector<std::vector<int>> waves(std::size_t(period) * period);
  int tiles = 0;
  for (int t = 0; t < tx * ty; ++t) {
    const int x0 = (t % tx) * kTile, y0 = (t / tx) * kTile;
    if (x0 + kTile <= region.x0 || x0 >= region.x1 || y0 + kTile <= region.y0 || y0 >= region.y1) continue;
    waves[std::size_t((t / tx) % period) * period + (t % tx) % period].push_back(t), ++tiles;
  }
  const int RW = region.width(), RH = region.height();

  // Distributed (docs/distributed.md): tile j of each wave belongs to rank j mod N. After the
  // wave every rank sends the pixel state of its tiles' footprints (the tile, plus the splat
  // margin when splatting) and copies the others' into its film. Footprints within a wave are
  // disjoint and each was computed by one rank exactly as one process computes it, so every
  // rank holds the single-process film, bit for bit, before the next wave.
  const LocalProcessGroup alone;
  const ProcessGroup& group = opt.group ? *opt.group : alone;
  const int nranks = group.size(), me = group.rank();
  RankStats mine;
  mine.rank = me;
  tbb::enumerable_thread_specific<int64_t> traced(0);
  const int spread = mode == Reconstruction::Splat ? pr.splat_margin() : 0;  // pixels a tile's splats reach
  auto footprint = [&](int t) {
    return PixelRect{std::max((t % tx) * kTile - spread, region.x0), std::min((t % tx) * kTile + kTile + spread, region.x1),
                     std::max((t / tx) * kTile - spread, region.y0), std::min((t / tx) * kTile + kTile + spread, region.y1)};
  };
  // Copies the footprints of `rank`'s tiles of `wave` to (pack) or from (unpack) `bytes`.
  auto blocks = [&](const std::vector<int>& wave, int rank, std::vector<std::byte>& bytes, bool pack) {
    std::size_t at = 1;  // bytes[0]: the rank was interrupted
    for (std::size_t j = std::size_t(rank); j < wave.size(); j += std::size_t(nranks)) {
      const PixelRect f = footprint(wave[j]);
      for (Film* fm : {&film, split ? &decision : nullptr}) {
        if (!fm) continue;
        for (int y = f.y0; y < f.y1; ++y) {
          const std::size_t n = sizeof(PixelAccum) * std::size_t(f.width());
          PixelAccum* row = &fm->at(f.x0 - region.x0, y - region.y0);
          if (pack) bytes.resize(at + n), std::memcpy(bytes.data() + at, row, n);
          else std::memcpy(row, bytes.data() + at, n);
          at += n;
        }
      }
    }
  };

  // One pass over the image: every pixel extends its prefix to end_of(x, y) samples.
  const bool stop_in_tile = nranks > 1 && opt.cancel;
  auto pass = [&](const char* label, auto&& end_of) {
    std::atomic<bool> cancelled{false};
    int64_t my_tiles = 0;
    for (const std::vector<int>& wave : waves) my_tiles += (int64_t(wave.size()) + nranks - 1 - me) / nranks;
    Progress progress(label, double(my_tiles), opt.quiet || me != 0);
    for (const std::vector<int>& wave : waves) {
      std::vector<std::size_t> own;
      for (std::size_t j = std::size_t(me); j < wave.size(); j += std::size_t(nranks)) own.push_back(j);
      mine.tiles += int64_t(own.size());
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, own.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k) {
          if (opt.cancel && opt.cancel->load(std::memory_order_relaxed)) {
            cancelled = true;
            return;
          }
          const int t = wave[own[k]];
          int x0 = std::max((t % tx) * kTile, region.x0), y0 = std::max((t / tx) * kTile, region.y0);
          int x1 = std::min((t % tx) * kTile + kTile, region.x1), y1 = std::min((t / tx) * kTile + kTile, region.y1);
          int64_t& local = rays.local();
          PixelSampleState ps(sampler);
          std::optional<PixelSampleState> pd;
          if (decider) pd.emplace(*decider);
          int64_t& count = traced.local();
          for (int y = y0; y < y1 && !(stop_in_tile && cancelled.load(std::memory_order_relaxed)); ++y)
            for (int x = x0; x < x1; ++x) {
              // Under mpirun a SIGKILL follows the SIGTERM within a second (docs/distributed.md):
              // stop at the next pixel, not after the tile, so the partial image gets out.
              if (stop_in_tile && opt.cancel->load(std::memory_order_relaxed)) {
                cancelled = true;
                break;
              }
              PixelAccum& px = film.at(x - region.x0, y - region.y0);
              int64_t begin = px.prefix, end = end_of(x - region.x0, y - region.y0);
              if (end <= begin) continue;
              const int64_t before = px.traced + (split ? decision.at(x - region.x0, y - region.y0).traced : 0);
              local += pr.run(x, y, begin, end, film, split ? &decision : nullptr, ps, pd ? &*pd : nullptr);
              count += px.traced + (split ? decision.at(x - region.x0, y - region.y0).traced : 0) - before;
            }
          progress.advance();
        }
      });
      if (nranks > 1) {
        // Every rank takes part in every exchange, interrupted or not, so none waits forever;
        // after one that any rank marks interrupted, all stop.
        const auto e0 = std::chrono::steady_clock::now();
        std::vector<std::byte> out(1, std::byte(cancelled ? 1 : 0));
        blocks(wave, me, out, true);
        mine.bytes_sent += int64_t(out.size()) * (nranks - 1);
        std::vector<std::vector<std::byte>> in = group.all_gather(out);
        for (int r = 0; r < nranks; ++r) {
          if (in[std::size_t(r)][0] != std::byte(0)) cancelled = true;
          if (r != me) blocks(wave, r, in[std::size_t(r)], false);
        }
        mine.exchange_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count();
      }
      if (cancelled) break;
    }
    stopped = stopped || cancelled;
    return !cancelled;
  };

  int rounds = 0;
  SamplerProfiler profiler;  // the passes only: the build and the image are not sampling work
  if (!ad.enabled) {
    pass("render", [&](int, int) { return int64_t(desc.sampler.spp); });
  } else if (pass("render (adaptive, round 0)", [&](int, int) { return int64_t(ad.min_spp); })) {
    // McCool–Fiume §5.1 / Cook §6: refine by extending prefixes. A pixel whose error is above
    // the threshold doubles its sample count; its 3x3 neighbours refine with it, so edges
    // are not left blocky. Samples already taken are never moved or discarded.
    AdaptiveMetric metric(ad);
    // In film coordinates (the rendered rectangle); the image mean is the crop's.
    std::vector<uint8_t> bad(std::size_t(RW) * RH), active(std::size_t(RW) * RH);
    const int cx0 = crop.x0 - region.x0, cy0 = crop.y0 - region.y0, CW = crop.width(), CH = crop.height();
    std::vector<double> row_mean(CH);
    for (;;) {
      if (metric.needs_image_mean()) {
        // Rows in parallel, then summed in order: the same mean at any thread count.
        tbb::parallel_for(0, CH, [&](int y) {
          double s = 0;
          for (int x = 0; x < CW; ++x) s += judged.at(cx0 + x, cy0 + y).mean_luminance();
          row_mean[y] = s / CW;
        });
        double s = 0;
        for (double r : row_mean) s += r;
        metric.set_image_mean(s / CH);
      }
      tbb::parallel_for(0, RH, [&](int y) {
        for (int x = 0; x < RW; ++x) bad[std::size_t(y) * RW + x] = !metric.converged(judged.at(x, y));
      });
      int64_t n_active = 0;
      for (int y = 0; y < RH; ++y)
        for (int x = 0; x < RW; ++x) {
          bool a = false;
          for (int dy = -1; dy <= 1 && !a; ++dy)
            for (int dx = -1; dx <= 1 && !a; ++dx) {
              int xx = x + dx, yy = y + dy;
              a = xx >= 0 && yy >= 0 && xx < RW && yy < RH && bad[std::size_t(yy) * RW + xx];
            }
          a = a && film.at(x, y).prefix < ad.max_spp;
          active[std::size_t(y) * RW + x] = a;
          n_active += a;
        }
      if (n_active == 0) break;
      ++rounds;
      std::string label = "render (adaptive, round " + std::to_string(rounds) + ")";
      if (!pass(label.c_str(), [&](int x, int y) {
            int64_t p = film.at(x, y).prefix;
            return active[std::size_t(y) * RW + x] ? std::min<int64_t>(2 * p, ad.max_spp) : p;
          }))
        break;
    }
  }
  RenderResult res;
  res.stats.sampler_profile = profiler.result();
  device.check();

  res.image = film.image(desc.film.exposure, crop.x0 - region.x0, crop.y0 - region.y0, crop.width(), crop.height());
  res.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.stats.build_seconds = build_seconds;
  res.stats.cpu_seconds = process_cpu_seconds() - cpu0;
  res.stats.build_cpu_seconds = build_cpu_seconds;
  for (int64_t r : rays) mine.rays += r;
  for (int64_t n : traced) mine.samples += n;
  mine.seconds = res.stats.seconds - build_seconds;
  res.stats.ranks = {mine};
  if (nranks > 1) {
    // Every rank's stats on every rank; the ray total is their sum (integers: exact).
    std::vector<std::byte> out(sizeof(RankStats));
    std::memcpy(out.data(), &mine, sizeof mine);
    res.stats.ranks.clear();
    for (const std::vector<std::byte>& b : group.all_gather(out)) {
      RankStats r;
      std::memcpy(&r, b.data(), sizeof r);
      res.stats.ranks.push_back(r);
    }
    // Only rank 0 prints warnings (sampling/core/warnings.h); the others' held lines (a
    // sampler's about a pixel only they rendered) go to it, each kind printed once.
    std::vector<std::byte> held;
    for (const std::string& h : take_held_warnings()) {
      const auto* c = reinterpret_cast<const std::byte*>(h.c_str());
      held.insert(held.end(), c, c + h.size() + 1);  // with its '\0'
    }
    const std::vector<std::vector<std::byte>> all = group.all_gather(held);
    if (me == 0)
      for (const std::vector<std::byte>& b : all) {
        std::vector<std::string> lines;
        for (std::size_t at = 0; at < b.size();) {
          lines.emplace_back(reinterpret_cast<const char*>(b.data() + at));
          at += lines.back().size() + 1;
        }
        print_held_warnings(lines);
      }
  }
  for (const RankStats& r : res.stats.ranks) res.stats.rays += r.rays;
  int64_t crop_samples = 0;  // the margin's samples are work done, but not the image's spp
  for (int y = 0; y < RH; ++y)
    for (int x = 0; x < RW; ++x) {
      int64_t n = film.at(x, y).traced;  // whether or not they counted
      res.stats.nonfinite_samples += film.at(x, y).dropped;
      if (split) res.stats.nonfinite_samples += decision.at(x, y).dropped, n += decision.at(x, y).traced;
      res.stats.samples += n;
      const int ix = x + region.x0, iy = y + region.y0;
      if (ix >= crop.x0 && ix < crop.x1 && iy >= crop.y0 && iy < crop.y1) crop_samples += n;
    }
  if (ad.enabled && (crop.width() < W || crop.height() < H) && !opt.quiet &&
      (rounds > margin_rounds || metric_needs_mean))
    warn(std::string("pdrt: warning: the crop window of an adaptive render may differ from the full render's crop (") +
         (metric_needs_mean ? "error-per-sample compares with the crop's mean" : "refinement ran past the rounds the crop's margin covers") + ")");
  if (res.stats.nonfinite_samples > 0 && !opt.quiet)
    warn("pdrt: warning: " + std::to_string(res.stats.nonfinite_samples) + " samples had a NaN or infinite value and were dropped");
  res.stats.spp_mean = double(crop_samples) / (double(crop.width()) * crop.height());
  res.stats.partial = stopped;
  res.stats.adaptive_rounds = rounds;
  res.stats.triangles = scene.triangle_count();
  // The arena's size capped by the global limit (set above when opt.threads > 0, or by a caller).
  res.stats.threads = int(std::min<std::size_t>(
      std::size_t(tbb::this_task_arena::max_concurrency()),
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
  return res;
}

}  // namespace pdrt
