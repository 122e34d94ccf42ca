#pragma once
// The accepted samples of a 1-D or 2-D Gamito–Maddock run on a uniform grid of cells at most
// d / sqrt(n) wide, so that a cell holds at most one sample (the paper's per-leaf sample
// lists, §4.1/§4.2, become range queries here; GamitoSampleGrid is the chained grid for
// more dimensions). The grid has a border of ghost cells as deep as the widest query: on
// the torus they hold the periodic images of the samples near the opposite side (§4.5),
// inside walls they stay empty. Every query is then one plain box of cells, with no
// wrapping, image shifts or clamping, and a bit per cell says which cells of the box hold
// a sample, so a query reads only those.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sampling/core/fast_floor.h"
#include "sampling/core/huge_page_allocator.h"

namespace pdrt {

template <int N>
class GamitoGhostGrid {
  static_assert(N == 1 || N == 2, "one sample per cell needs cells of diagonal <= d");

 public:
  // `max_reach`: the widest reach visit() and prefetch() will be asked for.
  GamitoGhostGrid(double dist, bool periodic, double max_reach) : periodic_(periodic) {
    res_ = std::max(1, int(std::ceil(std::sqrt(double(N)) / dist)));
    pad_ = int(max_reach * res_) + 2;
    side_ = res_ + 2 * pad_;
    std::size_t cells = 1;
    for (int k = 0; k < N; ++k) stride_[k] = cells, cells *= std::size_t(side_);
    cells_.assign(cells, Cell{});
    occupied_.assign(cells / 64 + 2, 0);
  }

  // Stores p in its cell and, on the torus, each image of p that falls in a ghost cell.
  void insert(const double* p) {
    int home[N];
    for (int k = 0; k < N; ++k) home[k] = std::min(int(p[k] * res_), res_ - 1);
    // Per axis, the shifts s (whole periods) that put p's cell inside the padded grid.
    int lo[N], hi[N], s[N];
    for (int k = 0; k < N; ++k) {
      lo[k] = hi[k] = 0;
      if (periodic_) {
        while (home[k] + (lo[k] - 1) * res_ >= -pad_) --lo[k];
        while (home[k] + (hi[k] + 1) * res_ < res_ + pad_) ++hi[k];
      }
      s[k] = lo[k];
    }
    for (;;) {
      std::size_t id = 0;
      for (int k = 0; k < N; ++k) id += std::size_t(home[k] + s[k] * res_ + pad_) * stride_[k];
      for (int k = 0; k < N; ++k) cells_[id].x[k] = p[k] + double(s[k]);
      occupied_[id >> 6] |= uint64_t(1) << (id & 63);
      int k = 0;
      while (k < N && s[k] == hi[k]) s[k] = lo[k], ++k;
      if (k == N) return;
      ++s[k];
    }
  }

  // Calls f(q, cell) for every sample within `reach` of p on every axis (and some more), row
  // after row, until f returns true; returns whether it did. q is the sample or periodic
  // image stored there, so callers measure plain Euclidean distances; `cell` names the cell
  // for visit_cell(). The box is always `width` cells a side, the most a range of 2 reach
  // can touch. Its occupied cells are found from a bit per cell, all rows in one mask, so
  // the loop runs once per sample with a single hard-to-guess exit.
  template <class F>
  bool visit(const double* p, double reach, F&& f) const {
    const int width = span(reach), rows = N == 1 ? 1 : width;
    const std::size_t first = corner(p, reach, width), step = stride_[N - 1];
    if (width <= 8) {
      uint64_t mask = 0;  // row r of the box in bits 8r .. 8r + width - 1
      for (int r = 0; r < rows; ++r) mask |= occupied_bits(first + std::size_t(r) * step, width) << (8 * r);
      for (; mask != 0; mask &= mask - 1) {
        const int b = std::countr_zero(mask);
        const std::size_t id = first + std::size_t(b >> 3) * step + std::size_t(b & 7);
        if (f(static_cast<const double*>(cells_[id].x), uint32_t(id))) return true;
      }
      return false;
    }
    // A box wider than 8 cells (a grid of a few cells): every cell, an empty one as its far
    // point.
    for (int r = 0; r < rows; ++r)
      for (std::size_t id = first + std::size_t(r) * step, end = id + std::size_t(width); id < end; ++id)
        if (f(static_cast<const double*>(cells_[id].x), uint32_t(id))) return true;
    return false;
  }

  // Calls f(q) for the sample in one cell, if any; returns what f did.
  template <class F>
  bool visit_cell(uint32_t id, F&& f) const {
    const Cell& c = cells_[id];
    return c.x[0] != kFar && f(static_cast<const double*>(c.x));
  }

  void prefetch_cell(uint32_t id) const { __builtin_prefetch(&cells_[id]); }

  // The cell that stores (or would store) p, as visit() names it.
  uint32_t cell_of(const double* p) const {
    std::size_t id = 0;
    for (int k = 0; k < N; ++k) id += std::size_t(std::min(int(p[k] * res_), res_ - 1) + pad_) * stride_[k];
    return uint32_t(id);
  }

  // Starts loading the rows visit(p, reach) will read. Always inlined: GCC 12 finds an
  // out-of-line function that only prefetches "pure" and deletes its calls.
  [[gnu::always_inline]] void prefetch(const double* p, double reach) const {
    const int width = span(reach);
    const std::size_t first = corner(p, reach, width);
    for (int r = 0; r < (N == 1 ? 1 : width); ++r) {
      const auto from = reinterpret_cast<std::uintptr_t>(&cells_[first + std::size_t(r) * stride_[N - 1]]);
      for (std::uintptr_t line = from / 64; line <= (from + width * sizeof(Cell) - 1) / 64; ++line)
        __builtin_prefetch(reinterpret_cast<const void*>(line * 64));
    }
  }

 private:
  static constexpr double kFar = -1e9;

  struct Cell {
    Cell() { std::fill(x, x + N, kFar); }
    double x[N];  // empty: kFar
  };

  // The occupancy bits of cells id .. id + width - 1 (width <= 64), lowest first.
  uint64_t occupied_bits(std::size_t id, int width) const {
    const std::size_t word = id >> 6;
    const unsigned __int128 both = static_cast<unsigned __int128>(occupied_[word + 1]) << 64 | occupied_[word];
    return uint64_t(both >> (id & 63)) & (width >= 64 ? ~uint64_t(0) : (uint64_t(1) << width) - 1);
  }

  int span(double reach) const { return std::min(int(2.0 * reach * res_) + 2, side_); }

  // The first cell of the box that visit(p, reach) reads.
  std::size_t corner(const double* p, double reach, int width) const {
    std::size_t id = 0;
    for (int k = 0; k < N; ++k)
      id += std::size_t(std::clamp(floor_int((p[k] - reach) * res_), -pad_, res_ + pad_ - width) + pad_) * stride_[k];
    return id;
  }

  int res_, pad_, side_;
  bool periodic_;
  std::size_t stride_[N];
  std::vector<Cell, HugePageAllocator<Cell>> cells_;
  std::vector<uint64_t> occupied_;  // a bit per cell: holds a sample (or image)
};

}  // namespace pdrt
