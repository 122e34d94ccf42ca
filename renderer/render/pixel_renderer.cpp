#include "renderer/render/pixel_renderer.h"

#include "renderer/render/camera_sample.h"

#include <algorithm>

namespace pdrt {

int64_t PixelRenderer::run(int x, int y, int64_t begin, int64_t end, Film& film, Film* decide, PixelSampleState& ps,
                           PixelSampleState* pd) const {
  CameraSampleRule rule{filter, mode};
  rule.lens = camera.has_aperture();
  rule.time = shutter;
  const int64_t budget = end;
  if (const Sampler& s = ps.sampler(); s.pixel_counts_vary())
    begin = s.samples_in_pixel(x, y, begin), end = s.samples_in_pixel(x, y, end);
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
  film.at(x - ox, y - oy).prefix = budget;
  if (mode == Reconstruction::Rank) film.at(x - ox, y - oy).norm = rule.rank_candidates * filter.mean_value();
  if (expected) film.at(x - ox, y - oy).norm = double(budget) * expected->at(x, y);
  return rays;
}

void PixelRenderer::splat(Film& film, float fx, float fy, const PathResult& pr, int half) const {
  const float r = filter.radius();
  const int x0 = std::max(ox, int(std::ceil(fx - 0.5f - r))),
            x1 = std::min(ox + film.width() - 1, int(std::floor(fx - 0.5f + r)));
  const int y0 = std::max(oy, int(std::ceil(fy - 0.5f - r))),
            y1 = std::min(oy + film.height() - 1, int(std::floor(fy - 0.5f + r)));
  for (int qy = y0; qy <= y1; ++qy)
    for (int qx = x0; qx <= x1; ++qx) {
      const float w = filter.eval(fx - (float(qx) + 0.5f), fy - (float(qy) + 0.5f));
      if (w != 0) film.at(qx - ox, qy - oy).add(pr.radiance, w, pr.albedo, pr.normal, pr.depth, half);
    }
}

}  // namespace pdrt
