#include "renderer/scene/pbrt/equal_area_octahedral.h"

#include "renderer/scene/equirect.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

Vec3 equal_area_square_to_sphere(double u0, double v0) {
  const double u = 2 * u0 - 1, v = 2 * v0 - 1, au = std::abs(u), av = std::abs(v);
  // Signed distance from the diamond |u| + |v| = 1: > 0 inside (upper hemisphere).
  const double sd = 1 - (au + av), r = 1 - std::abs(sd);
  const double phi = (r == 0 ? 1 : (av - au) / r + 1) * M_PI / 4;
  const double z = std::copysign(1 - r * r, sd);
  const double s = r * std::sqrt(std::max(0.0, 2 - r * r));
  return {float(std::copysign(std::cos(phi), u) * s), float(std::copysign(std::sin(phi), v) * s), float(z)};
}

std::array<double, 2> equal_area_sphere_to_square(const Vec3& d) {
  const double x = std::abs(d.x), y = std::abs(d.y), z = std::abs(d.z);
  const double r = std::sqrt(std::max(0.0, 1 - z));
  const double a = std::max(x, y), b = std::min(x, y);
  double phi = a == 0 ? 0 : std::atan(b / a) * 2 / M_PI;  // in [0, 1]: the angle within the octant
  if (x < y) phi = 1 - phi;
  double v = phi * r, u = r - v;
  if (d.z < 0) {
    std::swap(u, v);
    u = 1 - u, v = 1 - v;
  }
  u = std::copysign(u, double(d.x)), v = std::copysign(v, double(d.y));
  return {0.5 * (u + 1), 0.5 * (v + 1)};
}

namespace {

// Texel (x, y) of an n x n octahedral image, wrapped: leaving the square across an edge
// re-enters it mirrored about that edge's midpoint (pbrt-v4's WrapMode::OctahedralSphere).
Vec3 texel(const EnvironmentImage& img, int x, int y) {
  const int n = img.width;
  if (x < 0) x = -x - 1, y = n - 1 - y;
  if (x >= n) x = 2 * n - 1 - x, y = n - 1 - y;
  if (y < 0) y = -y - 1, x = n - 1 - x;
  if (y >= n) y = 2 * n - 1 - y, x = n - 1 - x;
  x = std::clamp(x, 0, n - 1), y = std::clamp(y, 0, n - 1);
  const float* p = &img.rgb[3 * (size_t(y) * size_t(n) + size_t(x))];
  return {p[0], p[1], p[2]};
}

Vec3 bilinear(const EnvironmentImage& img, double u, double v) {
  const double x = u * img.width - 0.5, y = v * img.height - 0.5;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = float(x - x0), fy = float(y - y0);
  return texel(img, x0, y0) * ((1 - fx) * (1 - fy)) + texel(img, x0 + 1, y0) * (fx * (1 - fy)) +
         texel(img, x0, y0 + 1) * ((1 - fx) * fy) + texel(img, x0 + 1, y0 + 1) * (fx * fy);
}

}  // namespace

EnvironmentImage octahedral_to_equirect(const EnvironmentImage& src, const std::function<Vec3(const Vec3&)>& to_light) {
  EnvironmentImage out;
  out.height = src.width, out.width = 2 * src.width;
  out.rgb.resize(size_t(out.width) * size_t(out.height) * 3);
  for (int j = 0; j < out.height; ++j)
    for (int i = 0; i < out.width; ++i) {
      Vec3 sum(0.0f);
      for (int s = 0; s < 4; ++s) {
        const double u = (i + 0.25 + 0.5 * (s & 1)) / out.width, v = (j + 0.25 + 0.5 * (s >> 1)) / out.height;
        const std::array<double, 2> st = equal_area_sphere_to_square(normalize(to_light(equirect_direction(u, v))));
        sum += bilinear(src, st[0], st[1]);
      }
      float* p = &out.rgb[3 * (size_t(j) * size_t(out.width) + size_t(i))];
      for (int c = 0; c < 3; ++c) p[c] = sum[c] * 0.25f;
    }
  return out;
}

}  // namespace pdrt
