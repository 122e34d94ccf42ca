#pragma once
// The leaves of the Gamito–Maddock tree that may still receive a sample, kept as one flat
// array of cells that all sit at the same subdivision level (see gamito_maddock.cpp for why
// the level is shared). All cells have the same volume, 1 unit of (1/res)^n, so the
// allowable volume is exactly live() units and a uniform index is the paper's
// volume-weighted descent (§4.1, Appendix A) without rounding.
//
// Dead cells stay in place as tombstones until compact(), which keeps the order: cells are
// grouped by their level-0 ancestor in scanline order, so a subdivision sweeps the sample
// grid in order and shares one neighbour query per level-0 cell. A uniform slot that holds
// a tombstone is a rejected draw, which leaves the others uniform over the live cells.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "sampling/core/huge_page_allocator.h"

namespace pdrt {

template <int N>
struct GamitoCell {
  static constexpr uint32_t kDead = UINT32_MAX, kNone = UINT32_MAX;
  static constexpr int kWitnesses = 2;
  uint32_t c[N];  // integer coordinates at the current level; c[0] == kDead: a tombstone
  // The paper's per-leaf sample list (§4.1), cut to the disks that overlap the cell most
  // when it was made: sample-grid cells (or kNone) that darts test before the full query.
  uint32_t near[kWitnesses];
};

template <int N>
class GamitoActiveCells {
 public:
  using Cell = GamitoCell<N>;
  static constexpr int kKids = 1 << N;

  // Every cell of the res^n grid (level 0), in scanline order.
  void fill(uint32_t res) {
    std::size_t total = 1;
    for (int k = 0; k < N; ++k) total *= res;
    cells_.resize(total);
    Cell cur{};
    std::fill(cur.near, cur.near + Cell::kWitnesses, Cell::kNone);
    for (Cell& c : cells_) {
      c = cur;
      for (int k = 0; k < N && ++cur.c[k] == res; ++k) cur.c[k] = 0;
    }
    live_ = total;
  }

  std::size_t live() const { return live_; }
  std::size_t slots() const { return cells_.size(); }
  const Cell& operator[](std::size_t i) const { return cells_[i]; }
  Cell& operator[](std::size_t i) { return cells_[i]; }
  const Cell* data() const { return cells_.data(); }

  bool dead(std::size_t i) const { return cells_[i].c[0] == Cell::kDead; }

  void kill(std::size_t i) {
    if (cells_[i].c[0] == Cell::kDead) return;
    cells_[i].c[0] = Cell::kDead;
    --live_;
  }

  // Drops the tombstones once they are most of the array (pick() would draw too often);
  // returns whether it did (indices change).
  bool compact_if_sparse() {
    if (live_ * 4 > cells_.size()) return false;
    std::size_t n = 0;
    for (const Cell& c : cells_)
      if (c.c[0] != Cell::kDead) cells_[n++] = c;
    cells_.resize(n);
    return true;
  }

  // Replaces every live cell by those of its children whose bit is set in
  // alive(cell, kids), a mask of 2^n bits (child j has bit k of j as its offset along axis
  // k); alive() fills in the witnesses of kids[j].
  template <class Alive>
  void subdivide(Alive&& alive) {
    next_.clear();
    next_.reserve(live_ * 2);
    Cell kids[kKids];
    for (const Cell& parent : cells_) {
      if (parent.c[0] == Cell::kDead) continue;
      uint32_t mask = alive(parent, kids);
      for (; mask != 0; mask &= mask - 1) {
        int j = __builtin_ctz(mask);
        for (int k = 0; k < N; ++k) kids[j].c[k] = parent.c[k] << 1 | uint32_t((j >> k) & 1);
        next_.push_back(kids[j]);
      }
    }
    cells_.swap(next_);
    live_ = cells_.size();
    next_.clear();
    next_.shrink_to_fit();
  }

 private:
  std::vector<Cell, HugePageAllocator<Cell>> cells_, next_;
  std::size_t live_ = 0;
};

}  // namespace pdrt
