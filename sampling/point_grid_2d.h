#pragma once
// Flat uniform 2-D grid for minimum-distance queries at one radius: the "grid-accelerated
// neighbour search" of McCool–Fiume §4 (Bridson 2007 step 0), specialised for 2-D. Cells
// are at least `reach` wide, so every point within `reach` of a query lies in the 3x3 block
// around its cell. Each cell keeps its points' coordinates in one contiguous run of slots;
// a cell narrower than sqrt(2) times the points' spacing holds at most 4 of them (5 points
// in a square of side s are within s/sqrt(2) of each other), more grow the slots.
//
// Per-axis differences are the floating-point operations of axis_delta(): x - q, plus one
// period when the neighbour cell lies across the torus edge. With at least 4 cells per axis
// that is axis_delta's wrap for every pair within one cell width (wider pairs differ only
// when both are at least half a period apart), so query results are bit-identical to the
// per-point modulo.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pdrt {

class PointGrid2D {
 public:
  explicit PointGrid2D(bool periodic) : periodic_(periodic) {}

  // Cells per axis for a reach: the most whose side is still >= reach (a hair of slack so
  // rounding in the cell index never puts a point within reach two cells away).
  static int cells_for(double reach) { return std::max(1, int(std::floor(1.0 / (reach * (1.0 + 1e-9))))); }
  // Below this many cells per axis the 3x3 block wraps onto itself; callers scan instead.
  static constexpr int kMinCells = 4;

  // Empties the grid and sizes its cells for `reach`.
  void reset(double reach) {
    res_ = cells_for(reach);
    stride_ = res_ + 2;  // one empty border cell on each side: no bounds checks
    count_.assign(std::size_t(stride_) * std::size_t(stride_), 0);
    slots_ = 4;
    xy_.assign(count_.size() * 2 * slots_, 0.0);
  }

  int resolution() const { return res_; }

  void insert(double x, double y) {
    std::size_t c = index(cell(x), cell(y));
    if (count_[c] == slots_) grow();
    double* q = &xy_[(c * slots_ + count_[c]++) * 2];
    q[0] = x, q[1] = y;
  }

  // Calls f(ex, ey, q) with (ex, ey) the wrapped difference (x, y) - q for every stored point
  // q in the 3x3 block around (x, y); stops at the first call that returns true and says
  // whether one did. Needs resolution() >= kMinCells.
  template <class F>
  [[gnu::always_inline]] bool any_near(double x, double y, F&& f) const {
    const int cx = cell(x), cy = cell(y);
    return any_in_block(cx, cx, cy, cy, [&](const double* q, double sx, double sy) {
      return f((x - q[0]) + sx, (y - q[1]) + sy, q);
    });
  }

  // The walk behind any_near, for the block of cells within one of columns cx0..cx1 and
  // rows cy0..cy1 (cx1 - cx0 and cy1 - cy0 are 0 or 1, so with kMinCells no cell comes
  // twice): f(q, sx, sy) gets each point and the period shifts that make
  // (x - q[0]) + sx, (y - q[1]) + sy the wrapped differences for (x, y) in those columns
  // and rows (wrong only for pairs at least a quarter period apart, beyond any reach).
  template <class F>
  [[gnu::always_inline]] bool any_in_block(int cx0, int cx1, int cy0, int cy1, F&& f) const {
    int col[4], row[4];
    double sx[4], sy[4];
    const int nx = span(cx0, cx1, col, sx), ny = span(cy0, cy1, row, sy);
    for (int j = 0; j < ny; ++j) {
      const std::size_t base = std::size_t(row[j]) * std::size_t(stride_);
      for (int i = 0; i < nx; ++i) {
        const std::size_t c = base + std::size_t(col[i]);
        const double* q = &xy_[c * slots_ * 2];
        for (int n = count_[c]; n > 0; --n, q += 2)
          if (f(q, sx[i], sy[j])) return true;
      }
    }
    return false;
  }

  // Column (row) of a coordinate.
  int cell(double x) const { return std::min(int(x * res_), res_ - 1); }

 private:
  // Border-padded indices of cells c0 - 1 .. c1 + 1 along one axis and their period shifts;
  // returns how many.
  [[gnu::always_inline]] int span(int c0, int c1, int* idx, double* shift) const {
    const int n = c1 - c0 + 3;
    for (int i = 0; i < n; ++i) {
      const int c = c0 - 1 + i;
      idx[i] = c + 1, shift[i] = 0.0;
      if (periodic_ && c < 0) idx[i] += res_, shift[i] = 1.0;
      if (periodic_ && c >= res_) idx[i] -= res_, shift[i] = -1.0;
    }
    return n;
  }
  std::size_t index(int cx, int cy) const { return std::size_t(cy + 1) * std::size_t(stride_) + std::size_t(cx + 1); }

  // A cell is full: double every cell's slots (only if the caller's spacing is smaller
  // than the cells assume).
  [[gnu::noinline]] void grow() {
    std::vector<double> wide(xy_.size() * 2, 0.0);
    for (std::size_t c = 0; c < count_.size(); ++c)
      for (unsigned k = 0; k < 2u * count_[c]; ++k) wide[c * slots_ * 4 + k] = xy_[c * slots_ * 2 + k];
    xy_.swap(wide);
    slots_ *= 2;
  }

  bool periodic_;
  int res_ = 0, stride_ = 0;
  unsigned slots_ = 4;
  std::vector<uint16_t> count_;  // points per cell
  std::vector<double> xy_;      // cell c's points at [c * slots_ * 2, ...), x then y
};

}  // namespace pdrt
