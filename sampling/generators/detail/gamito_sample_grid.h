#pragma once
// The accepted samples of a Gamito–Maddock run in 3 or more dimensions, bucketed on a
// uniform background grid with the coordinates stored in the cells, so a range query reads
// a few contiguous rows. It replaces the paper's per-leaf sample lists (§4.1, §4.2): "which
// disks can reach this cell" is a range query here. A grid of cells d / sqrt(n) wide, one
// sample each, would dwarf the point set in these dimensions, so cells are about d wide and
// chain further samples (1-D and 2-D: GamitoGhostGrid).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sampling/core/fast_floor.h"
#include "sampling/core/huge_page_allocator.h"

namespace pdrt {

template <int N>
class GamitoSampleGrid {
  static_assert(N >= 3, "1-D and 2-D runs use GamitoGhostGrid");

 public:
  GamitoSampleGrid(double dist, std::size_t expected, bool periodic) : periodic_(periodic) {
    double m = std::ceil(1.0 / dist);
    m = std::min(m, std::floor(std::pow(8.0 * double(expected), 1.0 / N)));
    res_ = std::max(1, int(m));
    std::size_t cells = 1;
    for (int k = 0; k < N; ++k) stride_[k] = cells, cells *= std::size_t(res_);
    cells_.assign(cells, Cell{});
  }

  void insert(const double* p) {
    Cell& c = cells_[index(p)];
    if (c.x[0] >= 0.0) {
      Cell extra = c;
      c.more = int32_t(overflow_.size());
      overflow_.push_back(extra);
    }
    std::copy(p, p + N, c.x);
  }

  // Calls f(q, cell) for every sample within `reach` of p on every axis (and possibly a
  // few more) until f returns true; returns whether it did. When periodic, q is each of the
  // sample's images (shifts in {-1, 0, 1} per axis) that lies in that range, so callers
  // measure plain Euclidean distances. `cell` names the grid cell that stores the sample
  // (see visit_cell()).
  template <class F>
  bool visit(const double* p, double reach, F&& f) const {
    if (!periodic_) return visit_walled(p, reach, f);
    // Per axis: the cells in range (unwrapped index in [-res, 2 res) when periodic) as
    // wrapped offsets and image shifts, so the loops below only read.
    int span[N], cur[N];
    for (int k = 0; k < N; ++k) {
      int lo = std::max(floor_int((p[k] - reach) * res_), -res_);
      int hi = std::min(floor_int((p[k] + reach) * res_), 2 * res_ - 1);
      span[k] = hi - lo + 1;
      if (span[k] <= 0) return false;
      if (axes_[k].size() < std::size_t(span[k])) axes_[k].resize(std::size_t(span[k]));
      for (int i = 0; i < span[k]; ++i) {
        int c = lo + i;
        Axis& a = axes_[k][std::size_t(i)];
        a.shift = c < 0 ? -1.0 : c >= res_ ? 1.0 : 0.0;
        a.offset = std::size_t(c < 0 ? c + res_ : c >= res_ ? c - res_ : c) * stride_[k];
      }
      cur[k] = 0;
    }
    const Axis* row0 = axes_[0].data();
    double image[N];
    for (;;) {
      // Axis 0 runs along a row of contiguous cells.
      std::size_t row = 0;
      for (int k = 1; k < N; ++k) {
        const Axis& a = axes_[k][std::size_t(cur[k])];
        row += a.offset;
        image[k] = a.shift;
      }
      for (int i = 0; i < span[0]; ++i) {
        const std::size_t id = row + row0[i].offset;
        for (const Cell* c = &cells_[id]; c->x[0] >= 0.0;) {
          double shifted[N];
          shifted[0] = c->x[0] + row0[i].shift;
          for (int k = 1; k < N; ++k) shifted[k] = c->x[k] + image[k];
          if (f(static_cast<const double*>(shifted), uint32_t(id))) return true;
          if (c->more < 0) break;
          c = &overflow_[std::size_t(c->more)];
        }
      }
      int k = 1;
      while (k < N && cur[k] == span[k] - 1) cur[k] = 0, ++k;
      if (k >= N) return false;
      ++cur[k];
    }
  }

  // visit() inside walls: no images, the cells in range are a plain box.
  template <class F>
  bool visit_walled(const double* p, double reach, F& f) const {
    int lo[N], hi[N], cur[N];
    for (int k = 0; k < N; ++k) {
      lo[k] = std::max(floor_int((p[k] - reach) * res_), 0);
      hi[k] = std::min(floor_int((p[k] + reach) * res_), res_ - 1);
      if (lo[k] > hi[k]) return false;
      cur[k] = lo[k];
    }
    for (;;) {
      std::size_t row = 0;
      for (int k = 1; k < N; ++k) row += std::size_t(cur[k]) * stride_[k];
      for (std::size_t id = row + std::size_t(lo[0]), last = row + std::size_t(hi[0]); id <= last; ++id)
        for (const Cell* c = &cells_[id]; c->x[0] >= 0.0;) {
          if (f(static_cast<const double*>(c->x), uint32_t(id))) return true;
          if (c->more < 0) break;
          c = &overflow_[std::size_t(c->more)];
        }
      int k = 1;
      while (k < N && cur[k] == hi[k]) cur[k] = lo[k], ++k;
      if (k >= N) return false;
      ++cur[k];
    }
  }

  // Calls f(q) for the samples stored in one cell (as stored: no periodic image) until f
  // returns true; returns whether it did.
  template <class F>
  bool visit_cell(uint32_t id, F&& f) const {
    for (const Cell* c = &cells_[id]; c->x[0] >= 0.0;) {
      if (f(static_cast<const double*>(c->x))) return true;
      if (c->more < 0) break;
      c = &overflow_[std::size_t(c->more)];
    }
    return false;
  }

  void prefetch_cell(uint32_t id) const { __builtin_prefetch(&cells_[id]); }

  // The cell that stores (or would store) p, as visit() names it.
  uint32_t cell_of(const double* p) const { return uint32_t(index(p)); }

 private:
  struct Cell {
    double x[N] = {-1.0};  // x[0] < 0: empty
    int32_t more = -1;     // the cell's previous sample in overflow_
  };

  struct Axis {
    std::size_t offset;  // the wrapped cell's index step along the axis
    double shift;        // the periodic image it stands for
  };
  std::size_t index(const double* p) const {
    std::size_t i = 0;
    for (int k = N - 1; k >= 0; --k) i = i * std::size_t(res_) + std::size_t(std::min(int(p[k] * res_), res_ - 1));
    return i;
  }

  int res_;
  bool periodic_;
  std::size_t stride_[N];
  mutable std::vector<Axis> axes_[N];  // visit()'s per-axis ranges
  std::vector<Cell, HugePageAllocator<Cell>> cells_;
  std::vector<Cell> overflow_;
};

}  // namespace pdrt
