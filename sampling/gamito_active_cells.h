#pragma once
// The leaves of the Gamito–Maddock tree that may still receive a sample, kept as one flat
// array of cells that all sit at the same subdivision level (see gamito_maddock.cpp for why
// the level is shared). All cells then have the same volume, 1 unit of (1/res)^n, so the
// allowable volume is exactly size() units and an index drawn uniformly below size() is the
// paper's volume-weighted descent (§4.1, Appendix A) without rounding. Dead cells are
// swap-removed; a subdivision replaces every cell by its surviving 2^n children (§4.2).
#include <cstdint>
#include <vector>

namespace pdrt {

template <int N>
struct GamitoCell {
  uint32_t c[N];  // integer coordinates at the current level
  bool operator==(const GamitoCell&) const = default;
};

template <int N>
class GamitoActiveCells {
 public:
  using Cell = GamitoCell<N>;
  static constexpr int kKids = 1 << N;

  // Every cell of the res^n grid (level 0).
  void fill(uint32_t res) {
    std::size_t total = 1;
    for (int k = 0; k < N; ++k) total *= res;
    cells_.resize(total);
    Cell cur{};
    for (Cell& c : cells_) {
      c = cur;
      for (int k = 0; k < N && ++cur.c[k] == res; ++k) cur.c[k] = 0;
    }
  }

  std::size_t size() const { return cells_.size(); }
  bool empty() const { return cells_.empty(); }
  const Cell& operator[](std::size_t i) const { return cells_[i]; }
  const Cell* data() const { return cells_.data(); }

  // Removes `cell` if it is still at index i (a batch of darts may have moved it since it
  // was drawn; a cell left behind is dead space that later darts reject, which is harmless).
  void remove_if_at(std::size_t i, const Cell& cell) {
    if (i >= cells_.size() || !(cells_[i] == cell)) return;
    cells_[i] = cells_.back();
    cells_.pop_back();
  }

  // Replaces every cell by those of its children whose bit is set in alive(cell), a mask of
  // 2^n bits (child j has bit k of j as its offset along axis k).
  template <class Alive>
  void subdivide(Alive&& alive) {
    next_.clear();
    next_.reserve(cells_.size() * 2);
    for (const Cell& parent : cells_) {
      uint32_t mask = alive(parent);
      for (; mask != 0; mask &= mask - 1) {
        int j = __builtin_ctz(mask);
        Cell kid;
        for (int k = 0; k < N; ++k) kid.c[k] = parent.c[k] << 1 | uint32_t((j >> k) & 1);
        next_.push_back(kid);
      }
    }
    cells_.swap(next_);
    next_.clear();
    next_.shrink_to_fit();
  }

 private:
  std::vector<Cell> cells_, next_;
};

}  // namespace pdrt
