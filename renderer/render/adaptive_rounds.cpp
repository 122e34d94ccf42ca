#include "renderer/render/adaptive_rounds.h"

#include "renderer/render/adaptive_metric.h"
#include "renderer/render/progressive_passes.h"
#include "sampling/core/progress.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace pdrt {

namespace {

// The mean luminance of the judged film over the crop (film coordinates). Rows in parallel,
// then summed in order: the same mean at any thread count.
double crop_mean(const Film& judged, const RenderRegion& region, std::vector<double>& row_mean) {
  const int cx0 = region.crop_x0(), cy0 = region.crop_y0(), CW = region.crop.width(), CH = region.crop.height();
  tbb::parallel_for(0, CH, [&](int y) {
    double s = 0;
    for (int x = 0; x < CW; ++x) s += judged.at(cx0 + x, cy0 + y).mean_luminance();
    row_mean[y] = s / CW;
  });
  double s = 0;
  for (double r : row_mean) s += r;
  return s / CH;
}

// Marks the pixels that refine this round (not converged, or next to one that is not, and
// below max_spp); returns how many.
int64_t mark_active(const AdaptiveMetric& metric, const AdaptiveDesc& ad, const RenderFilms& films,
                    std::vector<uint8_t>& bad, std::vector<uint8_t>& active) {
  const Film& judged = films.judged();
  const int RW = films.image.width(), RH = films.image.height();
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
      a = a && films.image.at(x, y).prefix < ad.max_spp;
      active[std::size_t(y) * RW + x] = a;
      n_active += a;
    }
  return n_active;
}

}  // namespace

int render_adaptive_rounds(const AdaptiveDesc& ad, const RenderRegion& region, RenderFilms& films, TilePasses& passes,
                           bool quiet, const std::function<void(int64_t)>& on_pass) {
  int rounds = 0;
  {
    // Round 0 in progressive passes, so that a stopped render has every pixel at some spp.
    Progress progress("render (adaptive, round 0)", passes.work([&](int, int) { return int64_t(ad.min_spp); }), quiet);
    // Every rank decides the next rounds from the whole film.
    if (render_progressive(passes, ad.min_spp, progress, on_pass, FilmsTo::Everyone) < ad.min_spp) return rounds;
  }
  AdaptiveMetric metric(ad);
  // In film coordinates (the rendered rectangle); the image mean is the crop's.
  const int RW = films.image.width(), RH = films.image.height();
  std::vector<uint8_t> bad(std::size_t(RW) * RH), active(std::size_t(RW) * RH);
  std::vector<double> row_mean(region.crop.height());
  for (;;) {
    if (metric.needs_image_mean()) metric.set_image_mean(crop_mean(films.judged(), region, row_mean));
    if (mark_active(metric, ad, films, bad, active) == 0) break;
    ++rounds;
    const auto end_of = [&](int x, int y) {
      int64_t p = films.image.at(x, y).prefix;
      return active[std::size_t(y) * RW + x] ? std::min<int64_t>(2 * p, ad.max_spp) : p;
    };
    Progress progress("render (adaptive, round " + std::to_string(rounds) + ")", passes.work(end_of), quiet);
    if (!passes.run(end_of, progress)) break;
  }
  return rounds;
}

}  // namespace pdrt
