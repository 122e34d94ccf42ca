#include "renderer/render/camera_sample.h"

#include "renderer/render/sample_dimensions.h"

#include "sampling/core/derived_seeds.h"
#include "sampling/core/rng.h"

namespace pdrt {

double rank_candidates(const Filter& filter, int64_t spp) { return double(spp) / filter.mean_keep(); }

namespace {

// The rank's random part, independent of every sampler family: a hash of (seed, pixel, index).
double rank_jitter(uint64_t seed, int x, int y, int64_t index) {
  uint64_t h =
      hash_combine(hash_combine(rank_jitter_seed(seed), uint64_t(uint32_t(x)) << 32 | uint32_t(y)), uint64_t(index));
  return unit_from_u64(h);
}

}  // namespace

bool get_camera_sample(const CameraSampleRule& rule, int x, int y, int64_t index, PixelSampleState& ps,
                       CameraSample* out) {
  ps.start_pixel_sample(x, y, index);
  const Filter& filter = rule.filter;
  const Vec2 u = ps.get_2d(Family::Pixel, kSaltFilmPoint);
  switch (rule.mode) {
    case Reconstruction::Importance: {
      FilterSample fs = filter.sample(u);
      out->film_x = float(x) + 0.5f + fs.x;
      out->film_y = float(y) + 0.5f + fs.y;
      out->weight = fs.weight;
      break;
    }
    case Reconstruction::Splat:
      // The pixel family's pattern at pixel scale (McCool–Fiume's P x P-pixel tiles); the
      // renderer weights the sample into every pixel whose filter covers it.
      out->film_x = float(x + u[0]);
      out->film_y = float(y + u[1]);
      out->weight = 1;
      break;
    case Reconstruction::Rank: {
      // McCool–Fiume §5.2 with a randomised rank: candidate i of c is kept when
      // i + xi < c * x, x = (f - min) / (max - min), so P(kept) sums to c * x over i and
      // the kept density is exactly c * x; the weight is f / x.
      const float r = filter.radius();
      const float ox = float(2 * u[0] - 1) * r, oy = float(2 * u[1] - 1) * r;
      const float f = filter.eval(ox, oy);
      const double xv = (double(f) - filter.min_value()) / (double(filter.max_value()) - filter.min_value());
      const double rank = double(index) + rank_jitter(ps.sampler().seed(), x, y, index);
      if (!(rank < xv * rule.rank_candidates) || rank < xv * rule.rank_candidates_before) return false;
      out->film_x = float(x) + 0.5f + ox;
      out->film_y = float(y) + 0.5f + oy;
      out->weight = float(f / xv);
      break;
    }
  }
  out->time = rule.time ? float(ps.get_1d(Family::Time, kSaltShutterTime)) : 0.0f;
  out->lens = rule.lens ? ps.get_2d(Family::Lens, kSaltLensPoint) : Vec2{0.5, 0.5};
  return true;
}

}  // namespace pdrt
