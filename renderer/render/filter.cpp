#include "renderer/render/filter.h"

#include "renderer/render/concentric_disk.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace {

// Mitchell–Netravali with B = C = 1/3, on x in [0, 2].
float mitchell_1d(float x) {
  const float B = 1.0f / 3, C = 1.0f / 3;
  x = std::abs(x);
  if (x >= 2) return 0;
  if (x > 1)
    return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6;
  return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6;
}

// pbrt-v4's 1-D Gaussian of standard deviation sigma.
float gaussian_1d(float x, float sigma) {
  return std::exp(-x * x / (2 * sigma * sigma)) / (std::sqrt(2 * float(kPi)) * sigma);
}

}  // namespace

Filter::Filter(const FilterDesc& d)
    : type_(d.type), radius_(d.radius), sigma_(d.type == FilterType::Gaussian ? d.sigma : 0) {
  // Cook's Gaussian: e^(-d^2) - e^(-w^2), d in pixels, w the radius (1.5 by default);
  // pbrt-v4's: g(x) - g(w) per axis.
  gauss_tail_ = sigma_ > 0 ? gaussian_1d(radius_, sigma_) : std::exp(-radius_ * radius_);
  max_ = eval(0, 0);
  for (int i = 0; i <= 256; ++i)
    for (int j = 0; j <= 256; ++j) min_ = std::min(min_, eval(radius_ * (i / 128.0f - 1), radius_ * (j / 128.0f - 1)));
  // Midpoint rule (eval is 0 on the square's edge, which a lattice through it would count).
  double sum = 0;
  const int m = 512;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      sum += eval(radius_ * float((i + 0.5) / (m / 2) - 1), radius_ * float((j + 0.5) / (m / 2) - 1));
  mean_ = sum / (double(m) * m);
  // pbrt-v4 tabulates 32 cells per pixel of radius; a cell's value is the mean |f| on a 5 x 5
  // lattice spanning the cell (corners pulled in by 1/1000 of a cell, as eval is 0 on the
  // square's edge), so a cell the support only clips still gets samples.
  const int n = std::clamp(int(std::ceil(32 * radius_)), 16, 256);
  std::vector<double> f(std::size_t(n) * n);
  const double cell = 2.0 * radius_ / n;
  auto at = [&](int i, int a) { return float(-radius_ + (i + 0.001 + a * (0.998 / 4)) * cell); };
  for (int iy = 0; iy < n; ++iy)
    for (int ix = 0; ix < n; ++ix) {
      double s = 0;
      for (int a = 0; a <= 4; ++a)
        for (int b = 0; b <= 4; ++b) s += std::abs(eval(at(ix, a), at(iy, b)));
      f[std::size_t(iy) * n + ix] = s / 25;
    }
  table_ = PiecewiseConstant2D(f, n, n, -radius_, radius_, -radius_, radius_);
  if (type_ == FilterType::Gaussian && sigma_ == 0) {
    // Radial support: a square table's cells on the circle would put samples where f = 0,
    // so the Gaussian is tabulated over s = d^2 in [0, r^2) instead (uniform s is uniform area).
    const int m = 256;
    std::vector<double> g(m);
    const double ds = double(radius_) * radius_ / m;
    for (int i = 0; i < m; ++i) {
      double sum = 0;
      for (int a = 0; a <= 4; ++a) sum += std::exp(-(i + 0.001 + a * (0.998 / 4)) * ds) - gauss_tail_;
      g[i] = sum / 5;
    }
    radial_ = PiecewiseConstant1D(g, 0, double(radius_) * radius_);
  }
}

FilterSample Filter::sample(std::array<double, 2> u) const {
  double pdf = 0;
  FilterSample s;
  if (type_ == FilterType::Box) {
    // Uniform: the table's inversion is the identity map, so skip it.
    s.x = float((2 * u[0] - 1) * radius_), s.y = float((2 * u[1] - 1) * radius_);
    s.weight = 4 * radius_ * radius_;
    return s;
  }
  if (radial_.size() > 0) {
    // The concentric map keeps the pattern's stratification and makes rho^2 uniform; the
    // radial table then moves rho^2 to s = d^2. Area density = pdf(s) / pi.
    auto [rho, phi] = concentric_disk_polar(u);
    double d = std::sqrt(radial_.sample(double(rho) * rho, &pdf)) * (rho < 0 ? -1.0 : 1.0);
    pdf /= double(kPi);
    s.x = float(d * std::cos(phi)), s.y = float(d * std::sin(phi));
  } else {
    auto p = table_.sample(u, &pdf);
    s.x = float(p[0]), s.y = float(p[1]);
  }
  float f = eval(s.x, s.y);
  s.weight = pdf > 0 ? float(f / pdf) : 0.0f;
  return s;
}

float Filter::eval(float x, float y) const {
  if (std::abs(x) >= radius_ || std::abs(y) >= radius_) return 0;
  switch (type_) {
    case FilterType::Box:
      return 1;
    case FilterType::Tent:
      return (1 - std::abs(x) / radius_) * (1 - std::abs(y) / radius_);
    case FilterType::Gaussian: {
      if (sigma_ > 0) return (gaussian_1d(x, sigma_) - gauss_tail_) * (gaussian_1d(y, sigma_) - gauss_tail_);
      float d2 = x * x + y * y;
      return d2 >= radius_ * radius_ ? 0.0f : std::exp(-d2) - gauss_tail_;
    }
    case FilterType::Mitchell:
      // The canonical filter spans 2 pixels; scale it to the requested radius.
      return mitchell_1d(2 * x / radius_) * mitchell_1d(2 * y / radius_);
  }
  return 0;
}

}  // namespace pdrt
