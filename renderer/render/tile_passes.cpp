#include "renderer/render/tile_passes.h"

#include "sampling/core/progress.h"

#include <tbb/parallel_for.h>

#include <chrono>
#include <optional>

namespace pdrt {

TilePasses::TilePasses(const TileWaves& tiles, RenderFilms& films, const PixelRenderer& pixels, const Sampler& sampler,
                       const Sampler* decider, const ProcessGroup& group, const RenderOptions& opt)
    : tiles_(tiles),
      films_(films),
      pixels_(pixels),
      sampler_(sampler),
      decider_(decider),
      group_(group),
      opt_(opt),
      exchange_(group, tiles, {&films.image, films.decision_or_null()}),
      stop_in_tile_(group.size() > 1 && opt.cancel) {
  mine_.rank = group.rank();
}

bool TilePasses::run(const char* label, const std::function<int64_t(int, int)>& end_of) {
  const int nranks = group_.size(), me = group_.rank();
  std::atomic<bool> cancelled{false};
  int64_t my_tiles = 0;
  for (const std::vector<int>& wave : tiles_.waves()) my_tiles += (int64_t(wave.size()) + nranks - 1 - me) / nranks;
  Progress progress(label, double(my_tiles), opt_.quiet || me != 0);
  for (const std::vector<int>& wave : tiles_.waves()) {
    std::vector<std::size_t> own;
    for (std::size_t j = std::size_t(me); j < wave.size(); j += std::size_t(nranks)) own.push_back(j);
    mine_.tiles += int64_t(own.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, own.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        if (opt_.cancel && opt_.cancel->load(std::memory_order_relaxed)) {
          cancelled = true;
          return;
        }
        render_tile(wave[own[k]], end_of, cancelled);
        progress.advance();
      }
    });
    if (nranks > 1 && exchange_.exchange(wave, cancelled, mine_)) cancelled = true;  // after it, all stop
    if (cancelled) break;
  }
  stopped_ = stopped_ || cancelled;
  return !cancelled;
}

void TilePasses::render_tile(int t, const std::function<int64_t(int, int)>& end_of, std::atomic<bool>& cancelled) {
  const auto t0 = std::chrono::steady_clock::now();
  const PixelRect region = tiles_.region(), p = tiles_.pixels(t);
  int64_t& rays = rays_.local();
  PixelSampleState ps(sampler_);
  std::optional<PixelSampleState> pd;
  if (decider_) pd.emplace(*decider_);
  int64_t& count = traced_.local();
  for (int y = p.y0; y < p.y1 && !(stop_in_tile_ && cancelled.load(std::memory_order_relaxed)); ++y)
    for (int x = p.x0; x < p.x1; ++x) {
      if (stop_in_tile_ && opt_.cancel->load(std::memory_order_relaxed)) {
        cancelled = true;
        break;
      }
      const int fx = x - region.x0, fy = y - region.y0;
      PixelAccum& px = films_.image.at(fx, fy);
      int64_t begin = px.prefix, end = end_of(fx, fy);
      if (end <= begin) continue;
      const int64_t before = films_.traced(fx, fy);
      rays += pixels_.run(x, y, begin, end, films_.image, films_.decision_or_null(), ps, pd ? &*pd : nullptr);
      count += films_.traced(fx, fy) - before;
    }
  busy_.local() += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

RankStats TilePasses::rank_stats() const {
  RankStats s = mine_;
  for (int64_t r : rays_) s.rays += r;
  for (int64_t n : traced_) s.samples += n;
  for (double b : busy_) s.tile_seconds += b;
  return s;
}

}  // namespace pdrt
