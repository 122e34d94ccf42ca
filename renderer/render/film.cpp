#include "renderer/render/film.h"

#include <algorithm>
#include <cmath>
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
  for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], L[k]), hi[k] = std::max(hi[k], L[k]);
  ++samples;
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

Image Film::image(float exposure_stops) const { return image(exposure_stops, 0, 0, width_, height_); }

Image Film::image(float exposure_stops, int x0, int y0, int width, int height) const {
  Image img;
  img.width = width, img.height = height;
  std::size_t n = std::size_t(width) * height;
  img.rgb.resize(3 * n), img.albedo.resize(3 * n), img.normal.resize(3 * n);
  img.samples.resize(n), img.variance.resize(n), img.depth.resize(n);
  const float scale = std::exp2(exposure_stops);
  for (std::size_t i = 0; i < n; ++i) {
    const PixelAccum& p = at(x0 + int(i % std::size_t(width)), y0 + int(i / std::size_t(width)));
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
  return img;
}

}  // namespace pdrt
