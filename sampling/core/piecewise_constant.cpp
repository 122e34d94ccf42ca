#include "sampling/core/piecewise_constant.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

PiecewiseConstant1D::PiecewiseConstant1D(const std::vector<double>& f, double lo, double hi)
    : f_(f.size()), cdf_(f.size() + 1, 0.0), lo_(lo), hi_(hi) {
  const std::size_t n = f.size();
  const double dx = (hi - lo) / double(n);
  for (std::size_t i = 0; i < n; ++i) f_[i] = std::abs(f[i]);
  for (std::size_t i = 0; i < n; ++i) cdf_[i + 1] = cdf_[i] + f_[i] * dx;
  integral_ = cdf_[n];
  if (integral_ > 0) {
    for (std::size_t i = 1; i <= n; ++i) cdf_[i] /= integral_;
  } else {
    // Nothing to follow: uniform, so that sampling still covers the domain.
    std::fill(f_.begin(), f_.end(), 1.0);
    for (std::size_t i = 1; i <= n; ++i) cdf_[i] = double(i) / double(n);
  }
  cdf_[n] = 1.0;
  guide_.resize(n);
  std::size_t o = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double u = double(j) / double(n);
    while (o + 1 < n && cdf_[o + 1] <= u) ++o;
    guide_[j] = uint32_t(o);
  }
}

double PiecewiseConstant1D::sample(double u, double* pdf, std::size_t* cell) const {
  const std::size_t n = f_.size();
  // The cell with cdf_[o] <= u < cdf_[o + 1]: zero-width cells are never chosen.
  std::size_t o = guide_[std::min(n - 1, std::size_t(std::max(0.0, u) * double(n)))];
  while (o + 1 < n && cdf_[o + 1] <= u) ++o;
  double width = cdf_[o + 1] - cdf_[o], du = u - cdf_[o];
  if (width > 0) du /= width;
  du = std::clamp(du, 0.0, 1.0);
  const double mass = integral_ > 0 ? integral_ : hi_ - lo_;  // of f_ (all ones when uniform)
  if (pdf) *pdf = f_[o] / mass;
  if (cell) *cell = o;
  double x = lo_ + (double(o) + du) / double(n) * (hi_ - lo_);
  return std::min(x, std::nextafter(hi_, lo_));
}

double PiecewiseConstant1D::pdf(double x) const {
  const std::size_t n = f_.size();
  if (!(x >= lo_ && x < hi_)) return 0.0;
  std::size_t o = std::min(n - 1, std::size_t((x - lo_) / (hi_ - lo_) * double(n)));
  const double mass = integral_ > 0 ? integral_ : hi_ - lo_;
  return f_[o] / mass;
}

PiecewiseConstant2D::PiecewiseConstant2D(const std::vector<double>& f, std::size_t nx, std::size_t ny, double x0,
                                         double x1, double y0, double y1)
    : x0_(x0), x1_(x1), y0_(y0), y1_(y1) {
  std::vector<double> row_mass(ny);
  rows_.reserve(ny);
  for (std::size_t iy = 0; iy < ny; ++iy) {
    rows_.emplace_back(
        std::vector<double>(f.begin() + std::ptrdiff_t(iy * nx), f.begin() + std::ptrdiff_t((iy + 1) * nx)), x0, x1);
    row_mass[iy] = rows_.back().integral();
  }
  marginal_ = PiecewiseConstant1D(row_mass, y0, y1);
}

std::array<double, 2> PiecewiseConstant2D::sample(std::array<double, 2> u, double* pdf) const {
  double py = 0, px = 0;
  std::size_t iy = 0;
  double y = marginal_.sample(u[1], &py, &iy);
  double x = rows_[iy].sample(u[0], &px);
  if (pdf) *pdf = px * py;
  return {x, y};
}

double PiecewiseConstant2D::pdf(double x, double y) const {
  if (!(x >= x0_ && x < x1_ && y >= y0_ && y < y1_)) return 0.0;
  std::size_t iy = std::min(rows_.size() - 1, std::size_t((y - y0_) / (y1_ - y0_) * double(rows_.size())));
  return marginal_.pdf(y) * rows_[iy].pdf(x);
}

}  // namespace pdrt
