#pragma once
// The 2-D values a sampler gives pixels, as a point set for the point-set checks.
#include "sampling/core/point_set.h"
#include "sampling/samplers/sampler.h"

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace pdrt::test {

// Samples 0 .. n-1 of `family` at `bounce` of each pixel in turn.
inline PointSet stream_points(const Sampler& s, const std::vector<std::array<int, 2>>& pixels, int n, Family family,
                              int bounce) {
  PointSet ps;
  ps.dim = 2;
  for (auto [x, y] : pixels)
    for (int i = 0; i < n; ++i) {
      const Vec2 v = s.get_2d(x, y, i, family, bounce);
      ps.coords.push_back(v[0]);
      ps.coords.push_back(v[1]);
    }
  return ps;
}

// Values first <= i < n of a (pixel, family, bounce) stream whose prepared form
// (Sampler::prepare of the window [first, n)) differs from get_1d / get_2d, bit for bit; -1
// when nothing was prepared or the window was not.
inline int prepared_mismatches(const Sampler& s, int px, int py, Family f, int bounce, uint32_t n, uint32_t first = 0) {
  PreparedStream p;
  p.first = first, p.want = n;
  s.prepare(px, py, f, bounce, &p);
  if (!p.coords || p.count < n || p.base > first) return -1;
  int bad = 0;
  for (uint32_t i = first; i < n; ++i) {
    if (family_dim(f) == 1) {
      bad += p.value(i, 0) != s.get_1d(px, py, i, f, bounce);
    } else {
      const Vec2 v = s.get_2d(px, py, i, f, bounce);
      bad += p.value(i, 0) != v[0] || p.value(i, 1) != v[1];
    }
  }
  return bad;
}

// Mean and standard error over `seeds` samplers (make(seed)) of pixel (px, py)'s estimate, from
// its samples [first, first + 4), of f(pixel, lens, time) = x y + u^2 + sin(pi t), whose
// integral is analytic_estimate_integral.
inline constexpr double analytic_estimate_integral = 0.25 + 1.0 / 3.0 + 2.0 / M_PI;
inline std::pair<double, double> analytic_estimate(const std::function<std::unique_ptr<Sampler>(uint64_t)>& make,
                                                   int px, int py, int first, int seeds = 2048) {
  double sum = 0, sum2 = 0;
  for (int seed = 0; seed < seeds; ++seed) {
    auto s = make(uint64_t(seed));
    double e = 0;
    for (int i = first; i < first + 4; ++i) {
      const Vec2 p = s->get_2d(px, py, i, Family::Pixel, 0), l = s->get_2d(px, py, i, Family::Lens, 0);
      e += p[0] * p[1] + l[0] * l[0] + std::sin(M_PI * s->get_1d(px, py, i, Family::Time, 0));
    }
    e /= 4;
    sum += e, sum2 += e * e;
  }
  const double mean = sum / seeds;
  return {mean, std::sqrt((sum2 / seeds - mean * mean) / seeds)};
}

}  // namespace pdrt::test
