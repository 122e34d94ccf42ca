#include "renderer/render/tile_passes.h"

#include "sampling/core/progress.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <chrono>
#include <functional>

namespace pdrt {

TilePasses::TilePasses(const TileWaves& tiles, RenderFilms& films, const PixelRenderer& pixels, const Sampler& sampler,
                       const Sampler* decider, const ProcessGroup& group, const RenderOptions& opt,
                       std::chrono::steady_clock::time_point start)
    : tiles_(tiles),
      films_(films),
      pixels_(pixels),
      states_(sampler, decider),
      group_(group),
      opt_(opt),
      exchange_(group, tiles, {&films.image, films.decision_or_null()}),
      stop_in_tile_(group.size() > 1 && (opt.cancel || opt.time_limit > 0)),
      deadline_(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(opt.time_limit))) {
  mine_.rank = group.rank();
  int count = 0;
  for (const std::vector<int>& wave : tiles.waves())
    for (int t : wave) count = std::max(count, t + 1);
  own_tile_.assign(std::size_t(count), 0);
  sampled_.assign(std::size_t(count), 0);
  for (int t : tiles.tiles_of(group.rank(), group.size())) own_tile_[std::size_t(t)] = 1;
  populate_own_tiles();
}

void TilePasses::populate_own_tiles() {
  std::vector<Film*> films{&films_.image};
  if (films_.split) films.push_back(&films_.decision);
  if (group_.size() == 1) {  // every tile: the films' rows in parallel chunks
    const int h = films_.image.height(), w = films_.image.width();
    tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& r) {
      for (Film* f : films) f->populate(0, w, r.begin(), r.end());
    });
    return;
  }
  const std::vector<int> mine = tiles_.tiles_of(group_.rank(), group_.size());
  const PixelRect& region = tiles_.region();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mine.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const PixelRect p = tiles_.footprint(mine[k]);
      for (Film* f : films) f->populate(p.x0 - region.x0, p.x1 - region.x0, p.y0 - region.y0, p.y1 - region.y0);
    }
  });
}

double TilePasses::calibrate(const std::vector<PixelRect>& blocks, std::size_t b0, std::size_t b1, int64_t end) {
  std::atomic<bool> cancelled{false};  // never set: the calibration is not interrupted
  const auto end_of = [end](int, int) { return end; };
  const auto busy = [this] {
    double s = 0;
    for (double b : busy_) s += b;
    return s;
  };
  const double before = busy();
  std::vector<BlockSnapshot> taken(b1 - b0);
  for (std::size_t k = b0; k < b1; ++k) sampled_[std::size_t(tiles_.tile_at(blocks[k].x0, blocks[k].y0))] = 1;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(b0, b1, 1), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      if (pixel(blocks[k].x0, blocks[k].y0).prefix > 0) taken[k - b0] = snapshot(blocks[k]);
      render_pixels(blocks[k], end_of, cancelled);
    }
  });
  for (BlockSnapshot& b : taken)
    if (!b.image.empty()) snapshots_.push_back(std::move(b));
  in_step_ = false;
  return busy() - before;
}

TilePasses::BlockSnapshot TilePasses::snapshot(const PixelRect& b) {
  BlockSnapshot s{b, pixel(b.x0, b.y0).prefix, {}, {}};
  each_accum(b, [&](const PixelAccum& image, const PixelAccum* decision) {
    s.image.push_back(image);
    if (decision) s.decision.push_back(*decision);
  });
  return s;
}

void TilePasses::restore_calibration() {
  if (snapshots_.empty()) return;
  // The pass every pixel of this rank's tiles ended (0 when stopped in the first pass: then the
  // calibration's first pass stays, as without the later ones).
  int64_t reached = INT64_MAX;
  for (int t : tiles_.tiles_of(group_.rank(), group_.size())) {
    const PixelRect p = tiles_.pixels(t);
    for (int y = p.y0; y < p.y1; ++y)
      for (int x = p.x0; x < p.x1; ++x) reached = std::min(reached, pixel(x, y).prefix);
  }
  int64_t target = INT64_MAX;
  for (const BlockSnapshot& s : snapshots_) target = std::min(target, s.end);
  target = std::max(target, reached);
  for (const BlockSnapshot& s : snapshots_) {
    if (s.end != target) continue;
    std::size_t i = 0;
    each_accum(s.rect, [&](PixelAccum& image, PixelAccum* decision) {
      image = s.image[i];
      if (decision) *decision = s.decision[i];
      ++i;
    });
  }
}

std::vector<std::size_t> TilePasses::own_tiles(const std::vector<int>& wave) const {
  return rank_tiles(wave.size(), group_.rank(), group_.size());
}

double TilePasses::work(const std::function<int64_t(int, int)>& end_of) const {
  const PixelRect& region = tiles_.region();
  const std::vector<int> mine = tiles_.tiles_of(group_.rank(), group_.size());
  // Exact in any order: the terms are whole numbers, their sum far below 2^53.
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mine.size()), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double total) {
        for (std::size_t k = r.begin(); k != r.end(); ++k) {
          const PixelRect p = tiles_.pixels(mine[k]);
          const bool read = sampled_[std::size_t(mine[k])] != 0;  // else every prefix is 0
          for (int y = p.y0; y < p.y1; ++y)
            for (int x = p.x0; x < p.x1; ++x) {
              const int fx = x - region.x0, fy = y - region.y0;
              const int64_t taken = read ? films_.image.at(fx, fy).prefix : 0;
              total += double(std::max<int64_t>(0, end_of(fx, fy) - taken));
            }
        }
        return total;
      },
      std::plus<double>());
}

bool TilePasses::run(const std::function<int64_t(int, int)>& end_of, Progress& progress, FilmsTo to) {
  std::atomic<bool> cancelled{false};
  std::fill(sampled_.begin(), sampled_.end(), uint8_t(1));  // and the exchanges may write any tile
  for (const std::vector<int>& wave : tiles_.waves()) {
    const std::vector<std::size_t> own = own_tiles(wave);
    mine_.tiles += int64_t(own.size());
    std::vector<uint8_t> took(own.size(), 0);  // the tile took samples
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, own.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        if (interrupted()) {
          cancelled = true;
          return;
        }
        const int64_t added = render_tile(wave[own[k]], end_of, cancelled);
        took[k] = added > 0;
        progress.advance(double(added));
      }
    });
    if (group_.size() > 1) {  // after an exchange in which any rank was stopped, all stop
      // When every rank held the same films before the wave, a tile that took no samples is
      // the same everywhere still: only the others travel (an adaptive round's few tiles).
      std::vector<std::size_t> changed;
      for (std::size_t k = 0; k < own.size(); ++k)
        if (took[k]) changed.push_back(own[k]);
      const std::vector<std::size_t>* only = in_step_ ? &changed : nullptr;
      if (to == FilmsTo::Everyone || tiles_.spread() > 0) {
        cancelled = exchange_.exchange(wave, cancelled, mine_, only) || cancelled;
        in_step_ = true;
      } else if (exchange_.any_interrupted(cancelled, mine_)) {
        cancelled = true, exchange_.exchange(wave, true, mine_, only);
        in_step_ = true;
      } else {
        in_step_ = false;
      }
    }
    if (cancelled) break;
  }
  stopped_ = stopped_ || cancelled;
  return !cancelled;
}

int64_t TilePasses::render_tile(int t, const std::function<int64_t(int, int)>& end_of, std::atomic<bool>& cancelled) {
  return render_pixels(tiles_.pixels(t), end_of, cancelled);
}

int64_t TilePasses::render_pixels(const PixelRect& p, const std::function<int64_t(int, int)>& end_of,
                                  std::atomic<bool>& cancelled) {
  const auto t0 = std::chrono::steady_clock::now();
  const PixelRect region = tiles_.region();
  int64_t added = 0;
  int64_t& rays = rays_.local();
  ThreadSamplerStates::Lease states = states_.lease();
  PixelSampleState& ps = states.sampler();
  PixelSampleState* pd = states.decider();
  int64_t& count = traced_.local();
  for (int y = p.y0; y < p.y1 && !(stop_in_tile_ && cancelled.load(std::memory_order_relaxed)); ++y)
    for (int x = p.x0; x < p.x1; ++x) {
      if (stop_in_tile_ && interrupted()) {
        cancelled = true;
        break;
      }
      const int fx = x - region.x0, fy = y - region.y0;
      PixelAccum& px = films_.image.at(fx, fy);
      int64_t begin = px.prefix, end = end_of(fx, fy);
      if (end <= begin) continue;
      added += end - begin;
      const int64_t before = films_.traced(fx, fy);
      rays += pixels_.run(x, y, begin, end, films_.image, films_.decision_or_null(), ps, pd);
      count += films_.traced(fx, fy) - before;
    }
  busy_.local() += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return added;
}

RankStats TilePasses::rank_stats() const {
  RankStats s = mine_;
  for (int64_t r : rays_) s.rays += r;
  for (int64_t n : traced_) s.samples += n;
  for (double b : busy_) s.tile_seconds += b;
  return s;
}

}  // namespace pdrt
