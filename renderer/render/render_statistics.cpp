#include "renderer/render/render_statistics.h"

#include "renderer/render/process_cpu_time.h"
#include "sampling/core/warnings.h"

#include <tbb/global_control.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace pdrt {

RenderClock::RenderClock() : t0_(std::chrono::steady_clock::now()), cpu0_(process_cpu_seconds()) {}

void RenderClock::build_done() {
  build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  build_cpu_seconds_ = process_cpu_seconds() - cpu0_;
}

void RenderClock::finish(RenderStats& stats) const {
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  stats.build_seconds = build_seconds_;
  stats.cpu_seconds = process_cpu_seconds() - cpu0_;
  stats.build_cpu_seconds = build_cpu_seconds_;
}

std::vector<RankStats> gather_rank_stats(const RankStats& mine, const ProcessGroup& group) {
  if (group.size() == 1) return {mine};
  std::vector<std::byte> out(sizeof(RankStats));
  std::memcpy(out.data(), &mine, sizeof mine);
  std::vector<RankStats> ranks;
  for (const std::vector<std::byte>& b : group.all_gather(out)) {
    RankStats r;
    std::memcpy(&r, b.data(), sizeof r);
    ranks.push_back(r);
  }
  return ranks;
}

SampleCounts& SampleCounts::operator+=(const SampleCounts& o) {
  samples += o.samples, dropped += o.dropped, crop_samples += o.crop_samples;
  crop_complete = std::min(crop_complete, o.crop_complete);
  return *this;
}

SampleCounts count_pixels(const RenderFilms& films, const RenderRegion& region, const PixelRect& r) {
  return tbb::parallel_reduce(
      tbb::blocked_range<int>(r.y0, r.y1), SampleCounts{},
      [&](const tbb::blocked_range<int>& rows, SampleCounts c) {
        for (int y = rows.begin(); y < rows.end(); ++y)
          for (int x = r.x0; x < r.x1; ++x) {
            const int fx = x - region.rect.x0, fy = y - region.rect.y0;
            const int64_t n = films.traced(fx, fy);  // whether or not they counted
            c.dropped += films.image.at(fx, fy).dropped + (films.split ? films.decision.at(fx, fy).dropped : 0);
            c.samples += n;
            if (region.in_crop(x, y))
              c.crop_samples += n, c.crop_complete = std::min(c.crop_complete, films.image.at(fx, fy).prefix);
          }
        return c;
      },
      [](SampleCounts a, const SampleCounts& b) { return a += b; });
}

void count_samples(const SampleCounts& c, const RenderRegion& region, RenderStats& stats) {
  for (const RankStats& r : stats.ranks) stats.rays += r.rays;
  stats.nonfinite_samples += c.dropped;
  stats.samples += c.samples;
  stats.spp_complete = c.crop_complete == INT64_MAX ? 0 : c.crop_complete;
  stats.spp_mean = double(c.crop_samples) / (double(region.crop.width()) * region.crop.height());
}

void warn_nonfinite(const RenderStats& stats, bool quiet) {
  if (stats.nonfinite_samples > 0 && !quiet)
    warn("pdrt: warning: " + std::to_string(stats.nonfinite_samples) +
         " samples had a NaN or infinite value and were dropped");
}

int worker_threads() {
  return int(std::min<std::size_t>(std::size_t(tbb::this_task_arena::max_concurrency()),
                                   tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
}

}  // namespace pdrt
