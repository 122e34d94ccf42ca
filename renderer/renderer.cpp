#include "renderer.h"

#include "embree_scene.h"
#include "errors.h"
#include "filter.h"
#include "light_sampler.h"
#include "path_integrator.h"
#include "poisson_sampler.h"
#include "progress.h"
#include "thin_lens_camera.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>

namespace pdrt {

std::unique_ptr<Sampler> make_scene_sampler(const SamplerDesc& d) {
  if (d.type == "poisson") return make_poisson_sampler(d.seed, default_tables());
  return make_sampler(d.type, d.seed);
}

void check_film_memory(int width, int height) {
  double need = double(width) * double(height) * double(Film::kBytesPerPixel);
  double have = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (need > 0.75 * have) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "film %dx%d needs %.1f GiB of buffers; this machine has %.1f GiB", width, height,
                  need / (1 << 30), have / (1 << 30));
    throw InputError(buf);
  }
}

namespace {

constexpr int kTile = 16;

struct PixelRenderer {
  const ThinLensCamera& camera;
  const PathIntegrator& integrator;
  const Filter& filter;
  const Sampler& sampler;
  int spp;
  bool rank_selection;

  // Samples [begin, end) of pixel (x, y); returns rays traced.
  int64_t run(int x, int y, int64_t begin, int64_t end, PixelAccum& acc) const {
    PixelSample ps(sampler);
    const float r = filter.radius(), fmin = filter.min_value(), fmax = filter.max_value();
    int64_t rays = 0;
    for (int64_t i = begin; i < end; ++i) {
      ps.start_pixel_sample(x, y, i);
      auto u = ps.get_2d(Family::Pixel);
      float ox = float(2 * u[0] - 1) * r, oy = float(2 * u[1] - 1) * r;
      float w = filter.eval(ox, oy);
      if (rank_selection) {
        // McCool–Fiume §5.2: keep sample i of n when its rank i/n is below the normalised
        // filter value x; the kept set has density ~ x, so the weight becomes f / x.
        float xv = (w - fmin) / (fmax - fmin);
        if (double(i + 1) / double(spp) > xv) continue;
        w = w / xv;
      } else if (w == 0) {
        continue;  // outside the filter's support: contributes nothing
      }
      float time = float(ps.get_1d(Family::Time, 0));
      Ray ray = camera.generate(float(x) + 0.5f + ox, float(y) + 0.5f + oy, ps.get_2d(Family::Lens), time);
      PathResult pr = integrator.trace(ray, ps);
      Vec3 L = is_finite(pr.radiance) ? pr.radiance : Vec3(0.0f);  // a NaN must not poison the pixel
      acc.add(L, w, pr.albedo, pr.normal, pr.depth);
      rays += pr.rays;
    }
    return rays;
  }
};

}  // namespace

RenderResult render(const SceneDesc& desc, const Sampler& sampler, const RenderOptions& opt) {
  check_film_memory(desc.film.width, desc.film.height);
  std::optional<tbb::global_control> limit;
  if (opt.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(opt.threads));
  auto t0 = std::chrono::steady_clock::now();

  EmbreeDevice device(opt.threads > 0 ? "threads=" + std::to_string(opt.threads) : "");
  EmbreeScene scene(desc, device);
  LightSampler lights(scene);
  PathIntegrator integrator(scene, lights, desc.integrator);
  ThinLensCamera camera(desc.camera, desc.film.width, desc.film.height);
  Filter filter(desc.film.filter);
  Film film(desc.film.width, desc.film.height);
  PixelRenderer pr{camera, integrator, filter, sampler, desc.sampler.spp, desc.film.filter.rank_selection};

  const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int tx = (desc.film.width + kTile - 1) / kTile, ty = (desc.film.height + kTile - 1) / kTile;
  tbb::enumerable_thread_specific<int64_t> rays(0);
  std::atomic<int> tiles_done{0};
  std::atomic<bool> stopped{false};
  Progress progress("render", double(tx) * ty, opt.quiet);
  tbb::parallel_for(tbb::blocked_range<int>(0, tx * ty, 1), [&](const tbb::blocked_range<int>& r) {
    for (int t = r.begin(); t != r.end(); ++t) {
      if (opt.cancel && opt.cancel->load(std::memory_order_relaxed)) {
        stopped = true;
        return;
      }
      int x0 = (t % tx) * kTile, y0 = (t / tx) * kTile;
      int x1 = std::min(x0 + kTile, desc.film.width), y1 = std::min(y0 + kTile, desc.film.height);
      int64_t& local = rays.local();
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) local += pr.run(x, y, 0, desc.sampler.spp, film.at(x, y));
      ++tiles_done;
      progress.advance();
    }
  });
  device.check();

  RenderResult res;
  res.image = film.image(desc.film.exposure);
  res.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  res.stats.build_seconds = build_seconds;
  for (int64_t r : rays) res.stats.rays += r;
  for (float s : res.image.samples) res.stats.samples += int64_t(s);
  res.stats.spp_mean = double(res.stats.samples) / (double(desc.film.width) * desc.film.height);
  res.stats.partial = stopped || tiles_done.load() < tx * ty;
  res.stats.triangles = scene.triangle_count();
  return res;
}

}  // namespace pdrt
