#include "renderer/render/camera_sample.h"

namespace pdrt {

bool get_camera_sample(const CameraSampleRule& rule, int x, int y, int64_t index, PixelSampleState& ps,
                       CameraSample* out) {
  ps.start_pixel_sample(x, y, index);
  const Filter& filter = rule.filter;
  const float r = filter.radius();
  auto u = ps.get_2d(Family::Pixel);
  float ox = float(2 * u[0] - 1) * r, oy = float(2 * u[1] - 1) * r;
  float w = filter.eval(ox, oy);
  if (rule.rank_selection) {
    // McCool–Fiume §5.2: keep sample i of n when its rank i/n is below the normalised
    // filter value x; the kept set has density ~ x, so the weight becomes f / x.
    const float fmin = filter.min_value(), fmax = filter.max_value();
    float xv = (w - fmin) / (fmax - fmin);
    if (double(index + 1) / double(rule.rank_budget) > xv) return false;
    w = w / xv;
  } else if (w == 0) {
    return false;  // outside the filter's support: contributes nothing
  }
  out->film_x = float(x) + 0.5f + ox;
  out->film_y = float(y) + 0.5f + oy;
  out->weight = w;
  out->time = float(ps.get_1d(Family::Time, 0));
  out->lens = ps.get_2d(Family::Lens);
  return true;
}

}  // namespace pdrt
