#include "renderer/render/film.h"

#include <sys/mman.h>
#include <tbb/blocked_range.h>
#include <unistd.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pdrt {

void PixelAccum::add(const Vec3& L, float weight, const Vec3& alb, const Vec3& n, float z, int half) {
  if (!is_finite(L)) {
    ++dropped;
    return;
  }
  double wt = weight;
  w += wt, w2 += wt * wt;
  rgb[0] += wt * L.x, rgb[1] += wt * L.y, rgb[2] += wt * L.z;
  double y = luminance(L);
  lum += wt * y, lum2 += wt * y * y;
  half_w[half] += wt, half_lum[half] += wt * y;
  double a = std::abs(wt);
  albedo[0] += a * alb.x, albedo[1] += a * alb.y, albedo[2] += a * alb.z;
  normal[0] += a * n.x, normal[1] += a * n.y, normal[2] += a * n.z;
  abs_w += a;
  if (std::isfinite(z)) depth += a * z, depth_w += a;
  for (int k = 0; k < 3; ++k)
    lo[k] = samples ? std::min(lo[k], L[k]) : L[k], hi[k] = samples ? std::max(hi[k], L[k]) : L[k];
  ++samples;
}

void Film::populate(int x0, int x1, int y0, int y1) {
#ifdef MADV_POPULATE_WRITE
  if (x0 >= x1 || y0 >= y1) return;
  static const uintptr_t page = uintptr_t(sysconf(_SC_PAGESIZE));
  const auto range = [&](const PixelAccum* a, const PixelAccum* b) {  // [a, b)
    const uintptr_t lo = reinterpret_cast<uintptr_t>(a) & ~(page - 1),
                    hi = (reinterpret_cast<uintptr_t>(b) + page - 1) & ~(page - 1);
    madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_POPULATE_WRITE);  // failure: faults as they come
    // And a write that changes nothing in each page: in a virtual machine a populated page's
    // first access still costs the host's fault (5-7 us on CI's kind), which would otherwise
    // land in the time estimate's calibration (a 1-spp render's rate 1.5-2x too slow) and in
    // the first tiles, not here, in parallel, before either.
    const uintptr_t from = reinterpret_cast<uintptr_t>(a);
    for (uintptr_t p = lo; p < hi; p += page)
      __atomic_fetch_or(reinterpret_cast<unsigned char*>(std::max(p, from)), 0, __ATOMIC_RELAXED);
  };
  if (x0 == 0 && x1 == width_)  // whole rows: one range
    return range(&at(0, y0), &at(0, y1 - 1) + width_);
  for (int y = y0; y < y1; ++y) range(&at(x0, y), &at(x1 - 1, y) + 1);
#else
  (void)x0, (void)x1, (void)y0, (void)y1;
#endif
}

double PixelAccum::mean_luminance() const { return w != 0 ? lum / w : 0.0; }

double PixelAccum::contrast(int k) const {
  if (samples < 2) return std::numeric_limits<double>::infinity();
  double s = double(hi[k]) + double(lo[k]);
  return s > 0 ? (double(hi[k]) - double(lo[k])) / s : 0.0;
}

Vec3 PixelAccum::value() const {
  const double d = norm > 0 ? norm : w;
  if (d == 0) return Vec3(0.0f);
  return Vec3(float(rgb[0] / d), float(rgb[1] / d), float(rgb[2] / d));
}

double PixelAccum::variance_of_mean() const {
  // Weighted sample variance times the effective 1/n of a weighted mean, sum w^2 / (sum w)^2.
  if (samples < 2 || w == 0) return 0.0;
  double mean = lum / w, var = std::max(0.0, lum2 / w - mean * mean);
  double n_eff = w * w / w2;
  return n_eff > 1 ? var / (n_eff - 1) : 0.0;
}

double PixelAccum::half_variance_of_mean() const {
  // Each half's mean has twice the variance of the whole mean, so their difference has four
  // times it.
  if (half_w[0] == 0 || half_w[1] == 0) return variance_of_mean();
  double d = half_lum[0] / half_w[0] - half_lum[1] / half_w[1];
  return d * d / 4;
}

void write_image_pixel(const PixelAccum& p, float scale, Image& img, std::size_t i) {
  Vec3 v = p.value() * scale;
  img.rgb[3 * i] = v.x, img.rgb[3 * i + 1] = v.y, img.rgb[3 * i + 2] = v.z;
  img.samples[i] = float(p.traced);
  img.variance[i] = float(p.variance_of_mean() * scale * scale);
  double inv = p.abs_w > 0 ? 1.0 / p.abs_w : 0.0;
  for (int k = 0; k < 3; ++k) {
    img.albedo[3 * i + k] = float(p.albedo[k] * inv);
    img.normal[3 * i + k] = float(p.normal[k] * inv);
  }
  img.depth[i] = p.depth_w > 0 ? float(p.depth / p.depth_w) : std::numeric_limits<float>::infinity();
}

Image Film::image(float exposure_stops) const { return image(exposure_stops, 0, 0, width_, height_); }

Image Film::image(float exposure_stops, int x0, int y0, int width, int height) const {
  Image img = sized_image(width, height);
  const float scale = std::exp2(exposure_stops);
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < width; ++x) write_image_pixel(at(x0 + x, y0 + y), scale, img, std::size_t(y) * width + x);
  });
  return img;
}

}  // namespace pdrt
