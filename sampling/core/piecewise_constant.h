#pragma once
// Tabulated distributions (pbrt-v4's PiecewiseConstant1D/2D): a non-negative function given
// on a regular grid, sampled by inverting its cumulative sum. The inversion is continuous and
// monotone, so a stratified or Poisson-disk input pattern stays well distributed after it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pdrt {

class PiecewiseConstant1D {
 public:
  PiecewiseConstant1D() = default;
  // `f` on n equal cells of [lo, hi]; negative values are taken as their absolute value.
  // An all-zero `f` samples uniformly.
  PiecewiseConstant1D(const std::vector<double>& f, double lo, double hi);
  // The point for u in [0, 1), its density (per unit of the domain) and its cell.
  double sample(double u, double* pdf, std::size_t* cell = nullptr) const;
  double pdf(double x) const;
  double integral() const { return integral_; }  // of |f| over [lo, hi]
  std::size_t size() const { return f_.size(); }

 private:
  std::vector<double> f_, cdf_;  // cdf_ has size() + 1 entries, from 0 to 1
  // guide_[j]: the first cell whose cdf end exceeds j / size(), so a lookup starts next to its
  // cell and scans O(1) cells on average instead of a binary search.
  std::vector<uint32_t> guide_;
  double lo_ = 0, hi_ = 1, integral_ = 0;
};

// A function on nx * ny cells of [x0, x1] x [y0, y1], row-major (f[iy * nx + ix]): the row is
// drawn from the marginal with u[1], the point in it from that row's conditional with u[0].
class PiecewiseConstant2D {
 public:
  PiecewiseConstant2D() = default;
  PiecewiseConstant2D(const std::vector<double>& f, std::size_t nx, std::size_t ny, double x0, double x1, double y0,
                      double y1);
  std::array<double, 2> sample(std::array<double, 2> u, double* pdf) const;
  double pdf(double x, double y) const;  // per unit area
  double integral() const { return marginal_.integral(); }

 private:
  std::vector<PiecewiseConstant1D> rows_;
  PiecewiseConstant1D marginal_;
  double x0_ = 0, x1_ = 1, y0_ = 0, y1_ = 1;
};

}  // namespace pdrt
