#include "renderer/compare/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pdrt {

namespace {

void check_same_size(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.rgb.size() != b.rgb.size())
    throw std::invalid_argument("image metrics: images differ in size");
}

float lum_at(const Image& im, std::size_t i) {
  return luminance(Vec3(im.rgb[3 * i], im.rgb[3 * i + 1], im.rgb[3 * i + 2]));
}

}  // namespace

double rmse(const Image& t, const Image& r) {
  check_same_size(t, r);
  double s = 0;
  for (std::size_t i = 0; i < t.rgb.size(); ++i) {
    double d = double(t.rgb[i]) - r.rgb[i];
    s += d * d;
  }
  return std::sqrt(s / double(t.rgb.size()));
}

double relative_mse(const Image& t, const Image& r, double eps) {
  check_same_size(t, r);
  double s = 0;
  for (std::size_t i = 0; i < t.rgb.size(); ++i) {
    double d = double(t.rgb[i]) - r.rgb[i];
    s += d * d / (double(r.rgb[i]) * r.rgb[i] + eps);
  }
  return s / double(t.rgb.size());
}

std::vector<float> error_map(const Image& t, const Image& r) {
  check_same_size(t, r);
  std::vector<float> e(std::size_t(t.width) * t.height);
  for (std::size_t i = 0; i < e.size(); ++i) e[i] = std::abs(lum_at(t, i) - lum_at(r, i));
  return e;
}

std::vector<unsigned char> firefly_mask(const Image& im, double ratio, double floor) {
  const int W = im.width, H = im.height;
  std::vector<unsigned char> mask(std::size_t(W) * H, 0);
  if (W <= 0 || H <= 0) return mask;
  std::vector<float> lum(mask.size());
  for (std::size_t i = 0; i < lum.size(); ++i) lum[i] = lum_at(im, i);
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      float v[9];
      int n = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int xx = std::clamp(x + dx, 0, W - 1), yy = std::clamp(y + dy, 0, H - 1);
          v[n++] = lum[std::size_t(yy) * W + xx];
        }
      std::nth_element(v, v + 4, v + 9);
      const float c = lum[std::size_t(y) * W + x];
      // A NaN is no firefly (the render drops non-finite samples); an infinity is one.
      if (double(c) > ratio * double(v[4]) && double(c) - v[4] > floor) mask[std::size_t(y) * W + x] = 1;
    }
  }
  return mask;
}

FireflyCount count_fireflies(const Image& test, const Image& reference, double ratio, double floor) {
  check_same_size(test, reference);
  const std::vector<unsigned char> t = firefly_mask(test, ratio, floor), r = firefly_mask(reference, ratio, floor);
  FireflyCount c;
  for (std::size_t i = 0; i < t.size(); ++i) {
    c.test += t[i];
    c.reference += r[i];
    c.extra += t[i] && !r[i];
  }
  return c;
}

std::vector<unsigned char> speck_mask(const Image& test, const Image& reference, double ratio, double floor) {
  check_same_size(test, reference);
  std::vector<unsigned char> mask(std::size_t(test.width) * test.height, 0);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    const double t = lum_at(test, i), r = lum_at(reference, i);
    mask[i] = t > ratio * r && t - r > floor;  // false for a NaN, true for an infinity
  }
  return mask;
}

long long count_specks(const Image& test, const Image& reference, double ratio, double floor) {
  long long n = 0;
  for (unsigned char m : speck_mask(test, reference, ratio, floor)) n += m;
  return n;
}

}  // namespace pdrt
