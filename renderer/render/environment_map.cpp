#include "renderer/render/environment_map.h"

#include "renderer/scene/equirect.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

EnvironmentMap::EnvironmentMap(int width, int height, std::vector<float> rgb, Vec3 scale, float rotation_deg,
                               EnvironmentSampling sampling)
    : width_(width), height_(height), rgb_(std::move(rgb)), scale_(scale) {
  const double r = double(rotation_deg) * M_PI / 180;
  cos_r_ = float(std::cos(r)), sin_r_ = float(std::sin(r));
  const int w = width_, h = height_;
  std::vector<double> lum(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) lum[std::size_t(y) * w + x] = luminance(texel(x, y));
  auto at = [&](int x, int y) {
    x = (x % w + w) % w, y = std::clamp(y, 0, h - 1);
    return lum[std::size_t(y) * w + x];
  };
  // The cell means of the interpolated luminance (1/8, 6/8, 1/8 per axis: the integral of
  // the linear interpolant over a cell whose centre is a texel centre).
  constexpr double k[3] = {0.125, 0.75, 0.125};
  std::vector<double> cell(lum.size());
  double mean = 0;
  for (int y = 0; y < h; ++y) {
    const double t0 = M_PI * y / h, t1 = M_PI * (y + 1) / h;
    const double solid_angle = 2 * M_PI / w * (std::cos(t0) - std::cos(t1));
    for (int x = 0; x < w; ++x) {
      double m = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) m += k[dy + 1] * k[dx + 1] * at(x + dx, y + dy);
      cell[std::size_t(y) * w + x] = m;
      mean += m * solid_angle;
    }
  }
  mean /= 4 * M_PI;
  irradiance_ = mean > 0 ? float(M_PI * mean) : 0.0f;
  const bool compensated = sampling == EnvironmentSampling::Compensated;
  const bool above_mean = std::any_of(cell.begin(), cell.end(), [&](double m) { return m > mean; });
  std::vector<double> f(lum.size());
  for (int y = 0; y < h; ++y) {
    const double sin_c = std::sin(M_PI * (y + 0.5) / h);
    for (int x = 0; x < w; ++x) {
      const double m = cell[std::size_t(y) * w + x];
      // Compensated with nothing above the mean: uniform over the sphere (pbrt-v4).
      f[std::size_t(y) * w + x] = (!compensated ? m : above_mean ? std::max(m - mean, 0.0) : 1.0) * sin_c;
    }
  }
  distribution_ = PiecewiseConstant2D(f, std::size_t(w), std::size_t(h), 0, 1, 0, 1);
}

Vec3 EnvironmentMap::texel(int x, int y) const {
  x = (x % width_ + width_) % width_, y = std::clamp(y, 0, height_ - 1);
  const float* p = &rgb_[3 * (std::size_t(y) * width_ + x)];
  return Vec3(p[0] * scale_.x, p[1] * scale_.y, p[2] * scale_.z);
}

Vec3 EnvironmentMap::lookup(double u, double v) const {
  const double x = u * width_ - 0.5, y = v * height_ - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const float tx = float(x - fx), ty = float(y - fy);
  const int x0 = int(fx), y0 = int(fy);
  return (texel(x0, y0) * (1 - tx) + texel(x0 + 1, y0) * tx) * (1 - ty) +
         (texel(x0, y0 + 1) * (1 - tx) + texel(x0 + 1, y0 + 1) * tx) * ty;
}

// The map's frame is the world's turned by rotation_deg about +y (right-handed):
// world = R m, m = R^-1 world.
Vec3 EnvironmentMap::direction(double u, double v) const {
  const Vec3 m = equirect_direction(u, v);
  return {m.x * cos_r_ + m.z * sin_r_, m.y, -m.x * sin_r_ + m.z * cos_r_};
}

std::array<double, 2> EnvironmentMap::uv(const Vec3& w) const {
  const Vec3 m(w.x * cos_r_ - w.z * sin_r_, w.y, w.x * sin_r_ + w.z * cos_r_);
  return equirect_uv(normalize(m));
}

Vec3 EnvironmentMap::radiance(const Vec3& w) const {
  if (empty()) return Vec3(0.0f);
  const auto [u, v] = uv(w);
  return lookup(u, v);
}

bool EnvironmentMap::sample(std::array<double, 2> u, Vec3* wi, Vec3* radiance, float* pdf) const {
  if (empty() || !(irradiance_ > 0)) return false;
  double p_uv;
  const std::array<double, 2> p = distribution_.sample(u, &p_uv);
  if (!(p_uv > 0)) return false;
  *wi = direction(p[0], p[1]);
  *radiance = lookup(p[0], p[1]);
  *pdf = solid_angle_pdf(p_uv, *wi);
  return *pdf > 0 && std::isfinite(*pdf);
}

// sin(theta) from the direction itself, as pdf() computes it: sqrt(x^2 + z^2) keeps its
// relative precision near the poles, where sin(acos(y)) of a float y does not.
float EnvironmentMap::solid_angle_pdf(double p_uv, const Vec3& w) {
  const double x = w.x, y = w.y, z = w.z;
  const double sin_theta = std::sqrt((x * x + z * z) / (x * x + y * y + z * z));
  return sin_theta > 0 ? float(p_uv / (2 * M_PI * M_PI * sin_theta)) : 0.0f;
}

float EnvironmentMap::pdf(const Vec3& w) const {
  if (empty() || !(irradiance_ > 0)) return 0;
  const auto [u, v] = uv(w);
  return solid_angle_pdf(distribution_.pdf(u, v), w);
}

}  // namespace pdrt
