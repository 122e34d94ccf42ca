// Gamito & Maddock 2009, "Accurate Multidimensional Poisson-Disk Sampling": maximal
// Poisson-disk sampling driven by a 2^n-tree of the space where samples may still go.
//
// Layout. The paper's tree starts at the root cube. Its top levels stay complete here: no
// disk covers a cell much wider than itself, so down to a base level whose cells are about
// the minimum distance wide the tree is kept implicitly, as per-level arrays of volume sums
// in Morton order. The base cells are stored in blocks of 2^n siblings (volumes and child
// links side by side); below them, nodes live in the same kind of block, taken from a pool
// and recycled (no per-node allocation). Instead
// of the paper's per-leaf sample lists (§4.1, §4.2), a grid of accepted samples answers
// "which disks can reach this leaf"; each leaf only keeps the paper's candidate bit (no disk
// touches it), so samples drawn in candidate leaves need no distance test at all. Random
// descents run in small batches so their cache misses overlap (see run()).
//
// Volumes are exact integers: a cell at level l has volume 2^(n (24 - l)) units, so the
// sums never round and one random integer below the root volume picks a leaf with
// probability proportional to its volume, i.e. uniformly over the space left (Appendix A).
#include "distance.h"
#include "generator.h"
#include "rng.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace pdrt {
namespace {

// §4: maximum subdivision level l_MAX; a leaf this deep is dropped when a sample in it fails.
constexpr int kMaxLevel = 24;

// Accepted samples bucketed on a uniform grid, coordinates stored in the cells so a range
// query reads a few contiguous rows. Up to 2-D the cells are at most d / sqrt(n) wide and so
// hold one sample each; in higher dimensions that grid would dwarf the point set, so cells
// are about d wide and chain further samples.
template <int N>
class SampleGrid {
 public:
  SampleGrid(double dist, std::size_t expected, bool periodic) : periodic_(periodic) {
    double m = std::ceil((kChained ? 1.0 : std::sqrt(double(N))) / dist);
    if (kChained) m = std::min(m, std::floor(std::pow(8.0 * double(expected), 1.0 / N)));
    res_ = std::max(1, int(m));
    std::size_t cells = 1;
    for (int k = 0; k < N; ++k) cells *= std::size_t(res_);
    cells_.assign(cells, Cell{});
  }

  void insert(const double* p) {
    Cell& c = cells_[index(p)];
    if constexpr (kChained) {
      if (c.x[0] >= 0.0) {
        Cell extra = c;
        c.more = int32_t(overflow_.size());
        overflow_.push_back(extra);
      }
    }
    std::copy(p, p + N, c.x);
  }

  // Calls f(q) for every sample within `reach` of p on every axis (and possibly a few
  // more). When periodic, q is each of the sample's images (shifts in {-1, 0, 1} per axis)
  // that lies in that range, so callers measure plain Euclidean distances.
  template <class F>
  void visit(const double* p, double reach, F&& f) const {
    int lo[N], hi[N], cur[N];
    int lowest = periodic_ ? -res_ : 0, highest = periodic_ ? 2 * res_ - 1 : res_ - 1;
    for (int k = 0; k < N; ++k) {
      lo[k] = std::max(int(std::floor((p[k] - reach) * res_)), lowest);
      hi[k] = std::min(int(std::floor((p[k] + reach) * res_)), highest);
      if (lo[k] > hi[k]) return;
      cur[k] = lo[k];
    }
    double shift[N], image[N];
    for (;;) {
      // Axis 0 runs along a row of contiguous cells.
      std::size_t row = 0;
      for (int k = N - 1; k >= 1; --k) row = row * std::size_t(res_) + std::size_t(unwrap(cur[k], shift[k]));
      row *= std::size_t(res_);
      // Along the row, images to the left, in and to the right of the cube in turn.
      for (int part = periodic_ ? -1 : 0; part <= (periodic_ ? 1 : 0); ++part) {
        int first = std::max(lo[0], part * res_), last = std::min(hi[0], part * res_ + res_ - 1);
        shift[0] = double(part);
        for (int x = first; x <= last; ++x) {
          for (const Cell* c = &cells_[row + std::size_t(x - part * res_)]; c->x[0] >= 0.0;) {
            if (periodic_) {
              for (int k = 0; k < N; ++k) image[k] = c->x[k] + shift[k];
              f(static_cast<const double*>(image));
            } else {
              f(static_cast<const double*>(c->x));
            }
            if constexpr (!kChained) break;
            else if (c->more < 0) break;
            else c = &overflow_[std::size_t(c->more)];
          }
        }
      }
      int k = 1;
      while (k < N && cur[k] == hi[k]) cur[k] = lo[k], ++k;
      if (k >= N) return;
      ++cur[k];
    }
  }

  // Starts loading the rows visit(p, reach) will read.
  void prefetch(const double* p, double reach) const {
    int lo[N], hi[N], cur[N];
    for (int k = 0; k < N; ++k) {
      lo[k] = int(std::floor((p[k] - reach) * res_));
      hi[k] = int(std::floor((p[k] + reach) * res_));
      cur[k] = lo[k];
    }
    for (int rows = 0; rows < 32; ++rows) {
      std::size_t row = 0;
      for (int k = N - 1; k >= 1; --k) row = row * std::size_t(res_) + std::size_t(std::clamp(cur[k], 0, res_ - 1));
      row *= std::size_t(res_);
      const char* first = reinterpret_cast<const char*>(&cells_[row + std::size_t(std::clamp(lo[0], 0, res_ - 1))]);
      const char* last = reinterpret_cast<const char*>(&cells_[row + std::size_t(std::clamp(hi[0], 0, res_ - 1))]);
      for (const char* line = first; line <= last + sizeof(Cell) - 1; line += 64) __builtin_prefetch(line);
      int k = 1;
      while (k < N && cur[k] == hi[k]) cur[k] = lo[k], ++k;
      if (k >= N) return;
      ++cur[k];
    }
  }

 private:
  static constexpr bool kChained = N > 2;
  struct Single {
    double x[N] = {-1.0};  // x[0] < 0: empty
  };
  struct Chained {
    double x[N] = {-1.0};
    int32_t more = -1;  // the cell's previous sample in overflow_
  };
  using Cell = std::conditional_t<kChained, Chained, Single>;

  // Cell index along an axis for an unwrapped index in [-res, 2 res), with the coordinate
  // shift of the periodic image it stands for.
  int unwrap(int c, double& shift) const {
    shift = c < 0 ? -1.0 : c >= res_ ? 1.0 : 0.0;
    return c < 0 ? c + res_ : c >= res_ ? c - res_ : c;
  }
  std::size_t index(const double* p) const {
    std::size_t i = 0;
    for (int k = N - 1; k >= 0; --k) i = i * std::size_t(res_) + std::size_t(std::min(int(p[k] * res_), res_ - 1));
    return i;
  }

  int res_;
  bool periodic_;
  std::vector<Cell> cells_;
  std::vector<Cell> overflow_;
};

template <int N>
class GamitoSampler {
  // Root volume is 2^(24 n) units: 64 bits hold it up to 2-D, 128 bits up to 5-D.
  using Vol = std::conditional_t<(N * kMaxLevel < 64), uint64_t, unsigned __int128>;
  static constexpr int kKids = 1 << N;
  // A child link is a block index or one of two leaf states (§4: candidate or not).
  static constexpr uint32_t kClear = UINT32_MAX;        // leaf no disk touches: a candidate
  static constexpr uint32_t kTouched = UINT32_MAX - 1;  // leaf some disk overlaps
  static bool is_leaf(uint32_t link) { return link >= kTouched; }

  struct Block {
    Vol vol[kKids];
    uint32_t link[kKids];
  };

  enum class Overlap { Out, Over, In };

  struct Point {
    Point() = default;
    explicit Point(const double* p) { std::copy(p, p + N, x); }
    double x[N];
  };

  // One random descent of Generate (§4.1) in flight: the leaf it reached and its point.
  struct Draw {
    Vol u;            // offset inside the current node
    std::size_t idx;  // current implicit node, then base block
    const Block* block;
    int level;
    uint32_t cell[N];
    double p[N];
  };

  // A leaf and the blocks above it: entry 0 is a base block, entries 1..depth pool blocks;
  // the leaf is slot[depth] of block[depth].
  struct Leaf {
    int level, depth;
    uint32_t cell[N];  // integer coordinates at `level`
    uint32_t link;     // kClear or kTouched
    uint32_t block[kMaxLevel + 1];
    int slot[kMaxLevel + 1];
  };

 public:
  GamitoSampler(double dist, bool periodic, uint64_t seed, std::size_t expected)
      : d_(dist), d2_(dist * dist), out2_(d2_ * (1 + 1e-9)), in2_(d2_ * (1 - 1e-9)), periodic_(periodic), rng_(seed),
        grid_(dist, expected, periodic) {
    for (int l = 0; l <= kMaxLevel; ++l) width_[l] = std::ldexp(1.0, -l);
    // Base cells at most the minimum distance wide (and more than half of it): wider ones
    // are hardly ever inside one disk, narrower ones cost memory for every cell. Their
    // number stays proportional to the expected points.
    int base = int(std::ceil(std::log2(1.0 / dist)));
    base = std::clamp(base, 1, kMaxLevel);
    while (base > 1 && std::ldexp(1.0, N * base) > 16.0 * double(expected)) --base;
    base_ = base;
    res_ = 1 << base_;
    levels_.resize(std::size_t(base_));
    for (int l = 0; l < base_; ++l) levels_[l].assign(std::size_t(1) << (N * l), cell_volume(l));
    Block full;
    std::fill(full.vol, full.vol + kKids, cell_volume(base_));
    std::fill(full.link, full.link + kKids, kClear);
    base_blocks_.assign(levels_[base_ - 1].size(), full);
    spread_.resize(std::size_t(res_));
    for (uint32_t x = 0; x < uint32_t(res_); ++x) {
      uint64_t m = 0;
      for (int i = 0; i < base_; ++i) m |= uint64_t((x >> i) & 1u) << (i * N);
      spread_[x] = m;
    }
  }

  // Figure 6: pick a leaf, try a sample in it; accept and Update, or Subdivide; until the
  // tree is empty (maximal up to the level-24 cells).
  //
  // Descents are made kBatch at a time against the same tree, interleaved so their cache
  // misses overlap, and then processed in order. The tree only ever shrinks, so a point
  // drawn uniformly from an earlier tree that still lies in the current one is a uniform
  // point of the current tree; a point whose cell was pruned in between is dropped, exactly
  // like a point landing in covered space. Every accepted point thus stays uniform over the
  // space left (Appendix A).
  std::vector<double> run(std::size_t expected) {
    std::vector<double> out;
    out.reserve(expected * N + N);
    Leaf leaf;
    while (levels_[0][0] != 0) {
      draw_batch();
      for (const Draw& t : draws_) {
        if (!locate(t.p, leaf)) continue;
        bool valid = true;
        if (leaf.link == kTouched) {
          gather(leaf);
          for (const Point& q : near_)
            if (distance2(t.p, q.x) < d2_) {
              valid = false;
              break;
            }
        }
        if (valid) {
          grid_.insert(t.p);
          out.insert(out.end(), t.p, t.p + N);
          update(t.p);
          continue;
        }
        // §4.1: an invalid sample refines its leaf; at l_MAX the whole leaf is dropped.
        uint32_t block = kTouched;
        Vol pruned = cell_volume(leaf.level);
        if (leaf.level < kMaxLevel) {
          sel_.resize(near_.size());
          for (std::size_t i = 0; i < near_.size(); ++i) sel_[i] = uint32_t(i);
          pruned = split(leaf.cell, leaf.level, kRefine, 0, near_.size(), block);
        }
        node_block(leaf.block[leaf.depth], leaf.depth).link[leaf.slot[leaf.depth]] = block;
        if (pruned != 0) shrink(leaf, pruned);
      }
    }
    return out;
  }

 private:
  // Levels one Subdivide call may refine at once: children straddling a disk are split
  // again right away instead of waiting for another failed sample.
  static constexpr int kRefine = 2;
  // Descents in flight at once (see run()).
  static constexpr int kBatch = 16;

  static Vol cell_volume(int level) { return Vol(1) << (N * (kMaxLevel - level)); }

  Block& node_block(uint32_t block, int depth) { return depth == 0 ? base_blocks_[block] : pool_[block]; }

  // Plain Euclidean: near_ already holds the periodic images.
  static double distance2(const double* a, const double* b) {
    double s = 0.0;
    for (int k = 0; k < N; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
    return s;
  }

  // Uniform integer in [0, n), n > 0.
  Vol draw_below(Vol n) {
    if constexpr (std::is_same_v<Vol, uint64_t>) {
      return rng_.below(n);
    } else {
      Vol m = n - 1;
      uint64_t top = uint64_t(m >> 64);
      int bits = top ? 128 - std::countl_zero(top) : 64 - std::countl_zero(uint64_t(m));
      Vol mask = bits >= 128 ? ~Vol(0) : (Vol(1) << bits) - 1;
      for (;;) {
        Vol r = (Vol(rng_.next_u64()) << 64 | rng_.next_u64()) & mask;
        if (r < n) return r;
      }
    }
  }

  // Index of the child a random offset u falls in; u becomes the offset inside it. Counts
  // the prefix sums not above u instead of branching on each (the branch is a coin toss).
  static int pick(const Vol* vol, Vol& u) {
    Vol sum = 0, before = 0;
    int c = 0;
    for (int k = 0; k < kKids - 1; ++k) {
      sum += vol[k];
      bool past = u >= sum;
      c += past;
      before = past ? sum : before;
    }
    u -= before;
    return c;
  }

  static void step(uint32_t* cell, int c) {
    for (int k = 0; k < N; ++k) cell[k] = cell[k] << 1 | uint32_t((c >> k) & 1);
  }

  // §4.1 Generate, descent half, for kBatch draws side by side: each child is taken with
  // probability volume / parent volume, by walking one random integer per draw down the
  // cumulative child volumes. Each step prefetches what the draw reads next.
  void draw_batch() {
    draws_.resize(kBatch);
    for (Draw& t : draws_) {
      t.u = draw_below(levels_[0][0]);
      t.idx = 0;
      std::fill(t.cell, t.cell + N, 0u);
    }
    for (int l = 1; l < base_; ++l)
      for (Draw& t : draws_) {
        int c = pick(&levels_[l][t.idx << N], t.u);
        t.idx = t.idx << N | std::size_t(c);
        step(t.cell, c);
        __builtin_prefetch(l + 1 < base_ ? static_cast<const void*>(&levels_[l + 1][t.idx << N]) : &base_blocks_[t.idx]);
      }
    std::size_t active = 0;
    for (Draw& t : draws_) t.block = &base_blocks_[t.idx], t.level = base_ - 1, ++active;
    while (active > 0)
      for (Draw& t : draws_) {
        if (t.block == nullptr) continue;
        int c = pick(t.block->vol, t.u);
        step(t.cell, c);
        ++t.level;
        uint32_t link = t.block->link[c];
        if (!is_leaf(link)) {
          t.block = &pool_[link];
          __builtin_prefetch(t.block);
          continue;
        }
        t.block = nullptr;
        --active;
        place(t);
        if (link == kTouched) grid_.prefetch(t.p, d_ + width_[t.level]);
      }
  }

  // Finds the current leaf holding p, or false when p's cell has been pruned.
  bool locate(const double* p, Leaf& leaf) const {
    uint64_t fixed[N], m = 0;
    for (int k = 0; k < N; ++k) {
      fixed[k] = uint64_t(p[k] * 0x1.0p52);  // exact: points are 52-bit fixed point
      m |= spread_[fixed[k] >> (52 - base_)] << k;
    }
    leaf.block[0] = uint32_t(m >> N);
    leaf.slot[0] = int(m & (kKids - 1));
    leaf.depth = 0;
    const Block* b = &base_blocks_[leaf.block[0]];
    int level = base_;
    for (;;) {
      int c = leaf.slot[leaf.depth];
      if (b->vol[c] == 0) return false;
      uint32_t link = b->link[c];
      if (is_leaf(link)) {
        leaf.link = link;
        break;
      }
      ++level;
      c = 0;
      for (int k = 0; k < N; ++k) c |= int((fixed[k] >> (52 - level)) & 1) << k;
      leaf.block[++leaf.depth] = link;
      leaf.slot[leaf.depth] = c;
      b = &pool_[link];
    }
    leaf.level = level;
    for (int k = 0; k < N; ++k) leaf.cell[k] = uint32_t(fixed[k] >> (52 - level));
    return true;
  }

  // Uniform point in the draw's leaf: 52-bit fixed point, so it is exact and inside the cell.
  void place(Draw& t) {
    int shift = 52 - t.level;
    for (int k = 0; k < N; ++k) {
      uint64_t bits = uint64_t(t.cell[k]) << shift | rng_.next_u64() >> (64 - shift);
      t.p[k] = double(bits) * 0x1.0p-52;
    }
  }

  // Appendix B: the nearest and farthest points of the cell from the sample decide Out / In;
  // when periodic, the sample's image nearest the cell decides (§4.5). Both verdicts keep
  // a relative margin of 1e-9 over rounding: Out leaves take samples without a distance
  // test, and In cells are dropped for good.
  Overlap classify(const uint32_t* cell, int level, const double* s) const {
    double w = width_[level], h = 0.5 * w, near2 = 0.0, far2 = 0.0;
    for (int k = 0; k < N; ++k) {
      double a = std::abs(axis_delta(s[k], (double(cell[k]) + 0.5) * w, periodic_));
      if (a > h) {
        near2 += (a - h) * (a - h);
        if (near2 > out2_) return Overlap::Out;
      }
      far2 += (a + h) * (a + h);
    }
    return far2 < in2_ ? Overlap::In : Overlap::Over;
  }

  // Every sample whose disk can reach the leaf (the paper's per-leaf list, §4.1).
  void gather(const Leaf& leaf) {
    double w = width_[leaf.level], centre[N];
    for (int k = 0; k < N; ++k) centre[k] = (double(leaf.cell[k]) + 0.5) * w;
    double reach = d_ + 0.5 * w * std::sqrt(double(N)), reach2 = reach * reach * (1 + 1e-9);
    near_.clear();
    grid_.visit(centre, d_ + 0.5 * w, [&](const double* q) {
      if (distance2(centre, q) < reach2) near_.push_back(Point(q));
    });
  }

  uint32_t alloc_block() {
    if (!free_.empty()) {
      uint32_t b = free_.back();
      free_.pop_back();
      return b;
    }
    pool_.emplace_back();
    return uint32_t(pool_.size() - 1);
  }

  // Returns a block and every block below it to the pool.
  void free_subtree(uint32_t block) {
    for (int c = 0; c < kKids; ++c)
      if (!is_leaf(pool_[block].link[c])) free_subtree(pool_[block].link[c]);
    free_.push_back(block);
  }

  // §4.1 book-keeping: the leaf and every ancestor lose the pruned volume. A node that
  // reaches zero is discarded; its children are all pruned already, so only its block is freed.
  void shrink(const Leaf& leaf, Vol pruned) {
    for (int i = leaf.depth; i >= 0; --i) {
      Block& b = node_block(leaf.block[i], i);
      int c = leaf.slot[i];
      if ((b.vol[c] -= pruned) == 0 && !is_leaf(b.link[c])) {
        free_.push_back(b.link[c]);
        b.link[c] = kTouched;
      }
    }
    std::size_t idx = leaf.block[0];
    for (int l = base_ - 1; l >= 0; --l, idx >>= N) levels_[l][idx] -= pruned;
  }

  // Appendix B for a disk already given as the image nearest the cell.
  Overlap overlap(const double* centre, double h, const double* q) const {
    double near2 = 0.0, far2 = 0.0;
    for (int k = 0; k < N; ++k) {
      double a = std::abs(q[k] - centre[k]), gap = std::max(a - h, 0.0);
      near2 += gap * gap;
      far2 += (a + h) * (a + h);
    }
    return near2 > out2_ ? Overlap::Out : far2 < in2_ ? Overlap::In : Overlap::Over;
  }

  // §4.2 Subdivide, `steps` levels at once, against the disks near_[sel_[first + i]],
  // i < count (every disk that reaches the cell): children inside one disk are pruned,
  // children outside all of them become candidates, and children straddling a disk are
  // split again, against just the disks they straddle, while steps remain. How far a leaf
  // is refined does not bias the sampling (refinement only prunes covered space, Appendix A).
  // Returns the pruned volume and the new block (kTouched when everything was pruned).
  Vol split(const uint32_t* cell, int level, int steps, std::size_t first, std::size_t count, uint32_t& block_out) {
    const double w = width_[level + 1], h = 0.5 * w;
    const std::size_t top = sel_.size();
    sel_.resize(top + kKids * count);  // child c lists the disks it straddles at top + c * count
    Overlap state[kKids];
    uint32_t kid[kKids][N];
    std::size_t straddled[kKids];
    int alive = 0;
    for (int c = 0; c < kKids; ++c) {
      double centre[N];
      for (int k = 0; k < N; ++k) {
        kid[c][k] = cell[k] << 1 | uint32_t((c >> k) & 1);
        centre[k] = (double(kid[c][k]) + 0.5) * w;
      }
      uint32_t* list = &sel_[top + c * count];
      std::size_t n = 0;
      state[c] = Overlap::Out;
      for (std::size_t i = 0; i < count; ++i) {
        uint32_t j = sel_[first + i];
        Overlap o = overlap(centre, h, near_[j].x);
        if (o == Overlap::In) {
          state[c] = o;
          break;
        }
        if (o == Overlap::Over) state[c] = o, list[n++] = j;
      }
      straddled[c] = n;
      alive += state[c] != Overlap::In;
    }
    block_out = kTouched;
    Vol child = cell_volume(level + 1), pruned = child * Vol(kKids - alive);
    if (alive != 0) {
      uint32_t block = alloc_block();
      for (int c = 0; c < kKids; ++c) {
        Vol cut = state[c] == Overlap::In ? child : 0;
        uint32_t link = state[c] == Overlap::Out ? kClear : kTouched;
        if (state[c] == Overlap::Over && steps > 1 && level + 1 < kMaxLevel) {
          cut = split(kid[c], level + 1, steps - 1, top + c * count, straddled[c], link);
          pruned += cut;
        }
        pool_[block].vol[c] = child - cut;
        pool_[block].link[c] = link;
      }
      if (pruned == cell_volume(level)) free_.push_back(block);
      else block_out = block;
    }
    sel_.resize(top);
    return pruned;
  }

  // §4.3 Update for a node the new disk reaches (`o` is In or Over): prune it when inside the
  // disk, otherwise mark a leaf as touched or recurse into its children. Returns the volume
  // pruned under the node.
  Vol update_node(uint32_t block, bool base, int c, const uint32_t* cell, int level, const double* s, Overlap o) {
    uint32_t link = node_block(block, !base).link[c];
    Vol pruned = node_block(block, !base).vol[c];
    if (o == Overlap::In) {
      if (!is_leaf(link)) free_subtree(link);
      link = kTouched;
    } else if (is_leaf(link)) {
      link = kTouched;
      pruned = 0;
    } else {
      pruned = 0;
      for (int k = 0; k < kKids; ++k) {
        if (pool_[link].vol[k] == 0) continue;
        uint32_t sub[N];
        for (int j = 0; j < N; ++j) sub[j] = cell[j] << 1 | uint32_t((k >> j) & 1);
        Overlap ko = classify(sub, level + 1, s);
        if (ko != Overlap::Out) pruned += update_node(link, false, k, sub, level + 1, s, ko);
      }
      if (pruned == node_block(block, !base).vol[c]) {
        free_.push_back(link);
        link = kTouched;
      }
    }
    Block& b = node_block(block, !base);
    b.link[c] = link;
    b.vol[c] -= pruned;
    return pruned;
  }

  // §4.3 Update for an accepted sample, over the base cells its disk can reach (wrapped when
  // periodic, §4.5: the nearest image is the only one that can cover a cell). Appendix B's
  // distances are separable per axis, so they are tabulated once per axis here; the implicit
  // levels above the base only carry sums.
  void update(const double* s) {
    const double w = width_[base_], h = 0.5 * w;
    int span[N], cur[N];
    for (int k = 0; k < N; ++k) {
      int lo = int(std::floor((s[k] - d_) * res_)), hi = int(std::floor((s[k] + d_) * res_));
      if (!periodic_) lo = std::max(lo, 0), hi = std::min(hi, res_ - 1);
      span[k] = std::min(hi - lo + 1, res_);
      cur[k] = 0;
      axis_[k].resize(std::size_t(span[k]));
      for (int i = 0; i < span[k]; ++i) {
        int c = ((lo + i) % res_ + res_) % res_;  // d may exceed the cube when periodic
        double a = std::abs(axis_delta(s[k], (double(c) + 0.5) * w, periodic_));
        AxisTerm& t = axis_[k][std::size_t(i)];
        t.near = a > h ? (a - h) * (a - h) : 0.0;
        t.far = (a + h) * (a + h);
        t.bits = spread_[std::size_t(c)] << k;
        t.cell = uint32_t(c);
      }
    }
    for (;;) {
      double near2 = 0.0, far2 = 0.0;
      for (int k = 0; k < N; ++k) near2 += axis_[k][std::size_t(cur[k])].near;
      if (near2 <= out2_) {
        uint64_t m = 0;
        uint32_t cell[N];
        for (int k = 0; k < N; ++k) {
          const AxisTerm& t = axis_[k][std::size_t(cur[k])];
          far2 += t.far;
          m |= t.bits;
          cell[k] = t.cell;
        }
        std::size_t idx = std::size_t(m >> N);
        int c = int(m & (kKids - 1));
        if (base_blocks_[idx].vol[c] != 0) {
          Overlap o = far2 < in2_ ? Overlap::In : Overlap::Over;
          Vol pruned = update_node(uint32_t(idx), true, c, cell, base_, s, o);
          if (pruned != 0)
            for (int l = base_ - 1; l >= 0; --l, idx >>= N) levels_[l][idx] -= pruned;
        }
      }
      int k = 0;
      while (k < N && cur[k] == span[k] - 1) cur[k] = 0, ++k;
      if (k == N) return;
      ++cur[k];
    }
  }

  double d_, d2_, out2_, in2_;
  bool periodic_;
  Rng rng_;
  SampleGrid<N> grid_;
  double width_[kMaxLevel + 1];
  int base_ = 1, res_ = 2;
  std::vector<std::vector<Vol>> levels_;  // implicit sums of levels 0..base_-1, Morton order
  std::vector<Block> base_blocks_;        // the base cells, grouped by parent
  std::vector<uint64_t> spread_;          // axis coordinate -> Morton bits
  std::vector<Block> pool_;               // explicit nodes below the base level
  std::vector<uint32_t> free_;            // released pool blocks
  struct AxisTerm {
    double near, far;  // squared nearest / farthest offsets of a base cell along one axis
    uint64_t bits;     // its Morton bits
    uint32_t cell;
  };
  std::vector<AxisTerm> axis_[N];  // Update's per-axis table
  std::vector<Draw> draws_;
  std::vector<Point> near_;    // disks that reach the current leaf (periodic images)
  std::vector<uint32_t> sel_;  // subsets of near_ during a split
};

template <int N>
std::vector<double> sample(double dist, bool periodic, uint64_t seed) {
  std::size_t expected = std::size_t(std::min(expected_count_for_radius(dist, N), 4.0e9)) + 1;
  return GamitoSampler<N>(dist, periodic, seed, expected).run(expected);
}

}  // namespace

PointSet generate_gamito(const GeneratorParams& p) {
  double dist = p.radius ? *p.radius : radius_for_count(*p.count, p.dim, p.periodic);
  PointSet ps;
  ps.dim = p.dim;
  ps.periodic = p.periodic;
  switch (p.dim) {
    case 1: ps.coords = sample<1>(dist, p.periodic, p.seed); break;
    case 2: ps.coords = sample<2>(dist, p.periodic, p.seed); break;
    case 3: ps.coords = sample<3>(dist, p.periodic, p.seed); break;
    case 4: ps.coords = sample<4>(dist, p.periodic, p.seed); break;
    default: ps.coords = sample<5>(dist, p.periodic, p.seed); break;
  }
  ps.radius.assign(ps.size(), dist);
  return ps;
}

}  // namespace pdrt
