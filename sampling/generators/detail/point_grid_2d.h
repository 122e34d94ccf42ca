#pragma once
// Flat uniform 2-D grid for minimum-distance queries: the "grid-accelerated neighbour
// search" of McCool–Fiume §4 with Bridson 2007's background grid (step 0), specialised for
// 2-D. Cells are narrower than r / sqrt(2) for the spacing r of the stored points, so a
// cell holds at most one point, stored in place (two doubles). Two thirds of the cells are
// empty, so each row also keeps an occupancy bitmask: a query takes the bits of its
// columns in one unaligned load and visits only the points. A border of padding cells
// holds, when periodic, copies of the cells across the torus edge (no bounds checks).
//
// Queries hand out each point with the period shift of the cell it was found in: the
// difference (x - q) + shift is the same floating-point operation as axis_delta()'s
// per-point wrap for every pair within a quarter period, and every query here reaches
// less than that (kMinCells), so results are bit-identical to the per-point modulo.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace pdrt {

class PointGrid2D {
 public:
  explicit PointGrid2D(bool periodic) : periodic_(periodic) {}

  // Cells per axis for points spaced at least r apart: the fewest whose side is below
  // r / sqrt(2) (with a hair of slack for rounding).
  static int cells_for(double r) { return int(std::floor(std::sqrt(2.0) / r * (1.0 + 1e-9))) + 1; }
  // Below this a query's reach (a radius plus a cell, under 3 cells) is not within a
  // quarter period, nor kPad cells within the padding; callers scan.
  static constexpr int kMinCells = 16;

  // Empties the grid and sizes its cells for spacing r.
  void reset(double r) {
    res_ = cells_for(r);
    stride_ = res_ + 2 * kPad;
    xy_.assign(std::size_t(stride_) * std::size_t(stride_) * 2, 0.0);
    row_bytes_ = std::size_t(stride_ + 7) / 8 + 8;  // + 8: a 64-bit load at any column stays inside
    occupied_.assign(std::size_t(stride_) * row_bytes_, 0);
    shift_.assign(std::size_t(stride_), 0.0);
    if (periodic_)
      for (int c = 0; c < kPad; ++c) shift_[std::size_t(c)] = 1.0, shift_[std::size_t(res_ + kPad + c)] = -1.0;
  }

  int resolution() const { return res_; }

  // Adds a point at least r (of the last reset) from every stored one.
  void insert(double x, double y) {
    const int cx = std::min(int(x * res_), res_ - 1), cy = std::min(int(y * res_), res_ - 1);
    put(cx, cy, x, y, true);
    if (!periodic_) return;
    // Ghost copies in the padding across each edge the cell is near.
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        const int gx = cx + ox * res_, gy = cy + oy * res_;
        if ((ox || oy) && gx >= -kPad && gx < res_ + kPad && gy >= -kPad && gy < res_ + kPad) put(gx, gy, x, y, false);
      }
  }

  // Calls f(q, sx, sy) for the point q of every cell meeting the square [x0, x1] x [y0, y1]
  // (reaching less than kPad cells past the domain, at most 57 cells wide), with
  // sx, sy the period shifts that make (x - q[0]) + sx, (y - q[1]) + sy the wrapped
  // differences for (x, y) in that square. Stops at the first call that returns true and
  // says whether one did.
  template <class F>
  [[gnu::always_inline]] bool any_in_box(double x0, double x1, double y0, double y1, F&& f) const {
    const int c0 = col(x0), c1 = col(x1), r0 = col(y0), r1 = col(y1);
    const uint64_t span = (uint64_t(2) << (c1 - c0)) - 1;
    for (int j = r0; j <= r1; ++j) {
      uint64_t bits;
      std::memcpy(&bits, &occupied_[std::size_t(j) * row_bytes_ + std::size_t(c0 >> 3)], 8);
      bits = bits >> (c0 & 7) & span;
      if (!bits) continue;
      const double* row = &xy_[std::size_t(j) * std::size_t(stride_) * 2];
      const double sy = shift_[std::size_t(j)];
      do {
        const int i = c0 + std::countr_zero(bits);
        if (f(row + 2 * i, shift_[std::size_t(i)], sy)) return true;
        bits &= bits - 1;
      } while (bits);
    }
    return false;
  }

 private:
  static constexpr int kPad = 4;

  // Padded column (row) of a coordinate in [-kPad / res, 1 + kPad / res).
  int col(double x) const { return int(x * res_ + kPad); }

  void put(int cx, int cy, double x, double y, bool own) {
    const std::size_t i = std::size_t(cx + kPad), j = std::size_t(cy + kPad);
    uint8_t& byte = occupied_[j * row_bytes_ + i / 8];
    if (own && (byte >> (i & 7) & 1))
      throw std::logic_error("PointGrid2D: two points in one cell (closer than the grid's spacing)");
    byte = uint8_t(byte | 1u << (i & 7));
    double* q = &xy_[(j * std::size_t(stride_) + i) * 2];
    q[0] = x, q[1] = y;
  }

  bool periodic_;
  int res_ = 0, stride_ = 0;
  std::size_t row_bytes_ = 0;
  std::vector<uint8_t> occupied_;  // per row, bit i: padded cell i holds a point
  std::vector<double> xy_;         // (x, y) of each padded cell's point
  std::vector<double> shift_;      // period shift of each padded column (= row)
};

}  // namespace pdrt
