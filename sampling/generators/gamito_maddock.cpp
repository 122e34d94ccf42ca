// Gamito & Maddock 2009, "Accurate Multidimensional Poisson-Disk Sampling": maximal
// Poisson-disk sampling driven by a subdivision of the space where samples may still go.
//
// Layout. The paper's 2^n-tree is kept only by its leaves, and all leaves sit at one level
// (GamitoActiveCells): a flat array of equal cells, so the volume-weighted descent of
// Generate (§4.1) is one uniform index, exact in integer units of the cell volume. The
// leaves start as a background grid of cells at most d / sqrt(n) wide (a cell holding a
// sample is inside its disk), and accepted samples live in a grid of their own
// (GamitoGhostGrid in 1-D/2-D, GamitoSampleGrid above) that answers the paper's per-leaf
// sample lists.
//
// Deviation from the paper, documented in docs/sampling.md: a failed sample does not
// subdivide its own leaf (§4.2). Darts are thrown in rounds; when a round at the current
// level succeeds too rarely, every leaf is subdivided at once and the children inside one
// disk are pruned (Appendix B). This keeps all leaves the same size. Uniformity is
// unaffected: a dart is uniform over the leaves, the leaves always contain the allowable
// set S_i, and a dart is accepted exactly when it lies in S_i, so an accepted sample is
// uniform over S_i (Eq. A.2, A.8) whatever the schedule of subdivisions and prunings.
#include "sampling/core/distance.h"
#include "sampling/generators/detail/gamito_active_cells.h"
#include "sampling/generators/detail/gamito_ghost_grid.h"
#include "sampling/generators/detail/gamito_sample_grid.h"
#include "sampling/core/huge_page_allocator.h"
#include "sampling/generators/detail/two_disk_cover.h"
#include "sampling/generators/generator.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace pdrt {
namespace {

// §4: cells are never narrower than the paper's level-24 cells (2^-24). At that level a
// dart removes its cell whatever happens, as the paper drops a leaf whose sample fails at
// l_MAX, so the result is maximal up to slivers of diameter sqrt(n) 2^-24 (Eq. 3).
constexpr int kMaxLevel = 24;

template <int N>
class GamitoSampler {
  using Cells = GamitoActiveCells<N>;
  using Cell = typename Cells::Cell;
  using Grid = std::conditional_t<N <= 2, GamitoGhostGrid<N>, GamitoSampleGrid<N>>;

 public:
  GamitoSampler(double dist, bool periodic, uint64_t seed, std::size_t expected)
      : d_(dist),
        d2_(dist * dist),
        in2_(d2_ * (1 - 1e-9)),
        periodic_(periodic),
        rng_(seed),
        grid_(make_grid(dist, expected, periodic)),
        res_(level0_res(dist, expected)) {
    last_ = 0;
    while ((uint64_t(res_) << last_) < (uint64_t(1) << kMaxLevel)) ++last_;
  }

  // Figure 6 in rounds: throw darts at the current level until they succeed too rarely,
  // then subdivide everything; until no cell is left.
  std::vector<double> run(std::size_t expected) {
    std::vector<double> out;
    out.reserve(expected * N + N);
    cells_.fill(res_);
    group_.resize(cells_.slots() + 1);
    index_groups();
    while (cells_.live() > 0) {
      std::size_t darts = std::size_t(double(cells_.live()) * kDartsPerCell), thrown = 0, tried = 0, hits = 0;
      // Four batches in flight: cells drawn, points made, darts screened by their witnesses,
      // darts tested. Darts still in flight when the round ends are dropped, as if never
      // thrown.
      const Fixed fixed = fixed_point();
      Batch batch[4];
      for (int j = 0; j < kBatch; ++j) draw(batch[0], j), draw(batch[1], j), draw(batch[2], j);
      for (int j = 0; j < kBatch; ++j) make(batch[0], j, fixed), make(batch[1], j, fixed), screen(batch[0], j);
      for (int cur = 0; thrown < darts && cells_.live() > 0; cur = (cur + 1) % 4) {
        advance_updates(false);
        Batch &drawn = batch[(cur + 3) % 4], &made = batch[(cur + 2) % 4], &screened = batch[(cur + 1) % 4];
        if constexpr (N <= 2) {
          // A dart of each batch at a time: the memory reads the stages start are spread
          // out instead of sixteen of a kind at once (they stalled on the fill buffers;
          // 10^6 points 1.68 -> 1.58 s). In 3-D and up the tests dominate and the stage
          // by stage loops ran 7% faster.
          for (int j = 0; j < kBatch; ++j)
            draw(drawn, j), make(made, j, fixed), screen(screened, j), hits += test(batch[cur], j, out, tried);
        } else {
          for (int j = 0; j < kBatch; ++j) draw(drawn, j);
          for (int j = 0; j < kBatch; ++j) make(made, j, fixed);
          for (int j = 0; j < kBatch; ++j) screen(screened, j);
          for (int j = 0; j < kBatch; ++j) hits += test(batch[cur], j, out, tried);
        }
        thrown += kBatch;
      }
      advance_updates(true);
      if (cells_.compact_if_sparse()) index_groups();
      if (level_ < last_ && double(hits) < kRefineBelow * double(tried)) subdivide();
    }
    return out;
  }

 private:
  static constexpr double kMaxCellsPerPoint = 32.0;
  // A round throws this many darts per live cell; the level is refined when fewer than
  // kRefineBelow of them succeed. 0.4 refines right after the first level-0 round (2-D: ~33%
  // accepted), whose second round would accept only ~7% (docs/sampling.md, speed).
  static constexpr double kDartsPerCell = 1.0;
  static constexpr double kRefineBelow = 0.4;
  // Darts per batch (see run()).
  static constexpr int kBatch = 16;
  // Samples that may reach one level-0 cell: a few in 2-D, more above (chained grid).
  static constexpr int kMaxNear = 1024;

  struct Batch {
    std::size_t idx[kBatch];
    bool live[kBatch];
    double p[kBatch][N];
    uint32_t near[kBatch][Cell::kWitnesses];
    bool rejected[kBatch];  // by a witness (screen())
    double q[kBatch][N];    // the witness's image near the dart, when rejected
  };

  // An accepted sample waiting for its Update, with the level-0 cells around it (their
  // index and, per axis in 2 bits, the periodic image of the sample that reaches them).
  static constexpr int kAround = N == 1 ? 3 : N == 2 ? 9 : N == 3 ? 27 : N == 4 ? 81 : 243;
  struct Pending {
    double x[N];
    int count;
    uint32_t base[kAround], image[kAround];
  };

  // A sample near a cell being subdivided, with the sample-grid cell that stores it.
  struct Near {
    double x[N];
    uint32_t id;
  };

  // Level-0 cells at most d / sqrt(n) wide, as long as their number stays proportional to
  // the points (5-D would need ~50 per point); wider cells are only pruned later.
  static uint32_t level0_res(double dist, std::size_t expected) {
    double m = std::ceil(std::sqrt(double(N)) / dist);
    m = std::min(m, std::floor(std::pow(kMaxCellsPerPoint * double(expected), 1.0 / N)));
    return uint32_t(std::clamp(m, 1.0, double(1u << 30)));
  }

  static Grid make_grid(double dist, std::size_t expected, bool periodic) {
    // The widest query is subdivide()'s: d beyond the centre of a level-0 cell.
    if constexpr (N <= 2)
      return Grid(dist, periodic, dist + 0.5 / double(level0_res(dist, expected)));
    else
      return Grid(dist, expected, periodic);
  }

  double width() const { return 1.0 / double(uint64_t(res_) << level_); }

  // §4.1 Generate, descent: a uniform slot (the volume-weighted descent; a tombstone is a
  // rejected draw, which leaves the others uniform over the live cells).
  void draw(Batch& b, int j) {
    b.idx[j] = std::size_t(rng_.below(cells_.slots()));
    __builtin_prefetch(cells_.data() + b.idx[j]);
  }

  // ... and a uniform point in the cell. Fixed point: c + u is exact with 53 - bits(res)
  // bits of u, and (c + u) / res < 1.
  struct Fixed {
    double res, unit;
    int frac;
  };
  Fixed fixed_point() const {
    const int frac = 53 - int(std::bit_width(uint64_t(res_) << level_));
    return {double(uint64_t(res_) << level_), std::ldexp(1.0, -frac), frac};
  }

  void make(Batch& b, int j, const Fixed& fx) {
    const Cell& cell = cells_[b.idx[j]];
    b.live[j] = cell.c[0] != Cell::kDead;
    if (!b.live[j]) return;
    for (int k = 0; k < N; ++k)
      b.p[j][k] = (double(cell.c[k]) + double(rng_.next_u64() >> (64 - fx.frac)) * fx.unit) / fx.res;
    std::copy(cell.near, cell.near + Cell::kWitnesses, b.near[j]);
    for (uint32_t id : cell.near)
      if (id != Cell::kNone) grid_.prefetch_cell(id);
  }

  // ... the test against the cell's witnesses first: most darts that fail, fail on them, and
  // a sample never goes away, so a dart they reject is rejected whatever the darts before
  // it do. In 1-D and 2-D the grid rows of the others are fetched for test().
  void screen(Batch& b, int j) {
    if (!b.live[j]) return;
    const double* p = b.p[j];
    double* q = b.q[j];
    bool conflict = false;
    for (int w = 0; w < Cell::kWitnesses && !conflict && b.near[j][w] != Cell::kNone; ++w)
      conflict = grid_.visit_cell(b.near[j][w], [&](const double* s) {
        if (distance_sq(p, s, N, periodic_) >= d2_) return false;
        for (int k = 0; k < N; ++k) q[k] = p[k] - axis_delta(p[k], s[k], periodic_);  // s's image near p
        return true;
      });
    b.rejected[j] = conflict;
    // In 3-D and up the rows are many and short (chained grid): fetching them cost more
    // than it saved (3-D, 5x10^4 points: 1.36 s with, 1.07 s without).
    if constexpr (N <= 2)
      if (!conflict) grid_.prefetch(p, d_);
  }

  // ... and the test against the samples near the point. The cells only ever shrink, so a
  // dart drawn from earlier cells that lands in S_i is still uniform over S_i.
  std::size_t test(const Batch& b, int j, std::vector<double>& out, std::size_t& tried) {
    if (!b.live[j]) return 0;
    ++tried;
    const double* p = b.p[j];
    double q[N];
    bool conflict = b.rejected[j];
    if (conflict) std::copy(b.q[j], b.q[j] + N, q);
    if (!conflict)
      conflict = grid_.visit(p, d_, [&](const double* s, uint32_t) {
        if (distance2(p, s) >= d2_) return false;
        std::copy(s, s + N, q);
        return true;
      });
    if (!conflict) {
      grid_.insert(p);
      out.insert(out.end(), p, p + N);
      queue_update(p);
    }
    // §4.1: the cell goes when the disk that decided the dart covers it, and at l_MAX always.
    const Cell& cell = cells_[b.idx[j]];
    if (!cells_.dead(b.idx[j]) && (level_ == last_ || covered(cell, conflict ? q : p))) cells_.kill(b.idx[j]);
    return conflict ? 0 : 1;
  }

  // §4.3 Update: the live cells in the 3^n level-0 cells around a new sample that its disk
  // covers are pruned, so darts and the next subdivision do not spend time on them. (Cells
  // farther away are hardly ever inside the disk; they are left to the coverage tests of
  // later darts and subdivisions.) The pruning runs two batches after the sample is
  // accepted, so the slot index and then the cells can be prefetched (advance_updates()).
  void queue_update(const double* p) {
    Pending& u = updates_[0].emplace_back();
    std::copy(p, p + N, u.x);
    u.count = 0;
    int home[N], off[N];
    for (int k = 0; k < N; ++k) home[k] = std::min(int(p[k] * res_), int(res_) - 1), off[k] = -1;
    for (;;) {
      std::size_t base = 0, stride = 1;
      uint32_t image = 0;
      bool inside = true;
      for (int k = 0; k < N; ++k) {
        int c = home[k] + off[k];
        if (c < 0 || c >= int(res_)) {  // across a wall, or the nearest image when periodic
          inside &= periodic_;
          image |= (c < 0 ? 1u : 2u) << (2 * k);
          c += c < 0 ? int(res_) : -int(res_);
        }
        base += std::size_t(c) * stride;
        stride *= res_;
      }
      if (inside) {
        __builtin_prefetch(groups_identity_ ? static_cast<const void*>(cells_.data() + base) : &group_[base]);
        u.base[u.count] = uint32_t(base);
        u.image[u.count++] = image;
      }
      int k = 0;
      while (k < N && off[k] == 1) off[k] = -1, ++k;
      if (k == N) return;
      ++off[k];
    }
  }

  // Moves the waiting Updates one step on: prefetch the cells of those queued in the last
  // batch, prune for those queued before. All are pruned when `flush` (the slots move next).
  void advance_updates(bool flush) {
    for (const Pending& u : updates_[1]) prune(u);
    updates_[1].clear();
    for (const Pending& u : updates_[0]) {
      if (flush)
        prune(u);
      else
        for (int i = 0; i < u.count; ++i) __builtin_prefetch(cells_.data() + group_first(u.base[i]));
    }
    if (!flush) updates_[0].swap(updates_[1]);
    updates_[0].clear();
  }

  void prune(const Pending& u) {
    for (int i = 0; i < u.count; ++i) {
      double s[N];  // the image of the sample next to the level-0 cell
      for (int k = 0; k < N; ++k) {
        uint32_t code = u.image[i] >> (2 * k) & 3u;
        s[k] = u.x[k] + (code == 1 ? 1.0 : code == 2 ? -1.0 : 0.0);
      }
      for (std::size_t j = group_first(u.base[i]); j < group_first(u.base[i] + 1); ++j) {
        if (cells_.dead(j)) continue;
        if (covered(cells_[j], s)) {
          cells_.kill(j);
        } else if constexpr (N == 2) {
          // The disk reaches into the cell: with the cell's first witness it may cover it
          // (two_disk_cover.h); if the cell has none yet, the disk becomes its witness.
          Cell& cell = cells_[j];
          const double w = width(), lo[2] = {double(cell.c[0]) * w, double(cell.c[1]) * w};
          if (near2(lo, w, s) >= d2_) continue;
          if (cell.near[0] == Cell::kNone) {
            cell.near[0] = grid_.cell_of(u.x);
            continue;
          }
          bool hit = false;
          grid_.visit_cell(cell.near[0], [&](const double* t0) {
            double t[2];
            for (int k = 0; k < 2; ++k) {
              const double centre = lo[k] + 0.5 * w;
              t[k] = centre - axis_delta(centre, t0[k], periodic_);  // the image nearest the cell
            }
            hit = square_in_two_disks(lo, w, s, t, in2_);
            return true;
          });
          if (hit) cells_.kill(j);
        }
      }
    }
  }

  // Where the cells of each level-0 cell start in cells_ (they are contiguous, in scanline
  // order of their level-0 cell); rebuilt whenever the slots move.
  void index_groups() {
    // At level 0, until the first compaction, slot b is level-0 cell b: no index to build
    // or read.
    groups_identity_ = level_ == 0 && cells_.slots() + 1 == group_.size();
    if (groups_identity_) return;
    std::size_t next = 0;  // first level-0 cell whose start is not written yet
    for (std::size_t i = 0; i < cells_.slots(); ++i) {
      std::size_t base = 0, stride = 1;
      for (int k = 0; k < N; ++k) base += std::size_t(cells_[i].c[k] >> level_) * stride, stride *= res_;
      while (next <= base) group_[next++] = uint32_t(i);
    }
    while (next < group_.size()) group_[next++] = uint32_t(cells_.slots());
  }

  std::size_t group_first(std::size_t b) const { return groups_identity_ ? b : group_[b]; }

  // Plain Euclidean: the grid hands out periodic images.
  static double distance2(const double* a, const double* b) {
    double s = 0.0;
    for (int k = 0; k < N; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
    return s;
  }

  // Appendix B: squared distance from s to the farthest point of the box [lo, lo + w]^n.
  static double far2(const double* lo, double w, const double* s) {
    double f = 0.0;
    for (int k = 0; k < N; ++k) {
      double a = std::max(std::abs(s[k] - lo[k]), std::abs(lo[k] + w - s[k]));
      f += a * a;
    }
    return f;
  }

  // ... and to its nearest point.
  static double near2(const double* lo, double w, const double* s) {
    double f = 0.0;
    for (int k = 0; k < N; ++k) {
      double a = std::max(std::max(lo[k] - s[k], s[k] - lo[k] - w), 0.0);
      f += a * a;
    }
    return f;
  }

  // The cell is inside the disk of s when its farthest corner is, with a relative margin of
  // 1e-9 over rounding (a covered cell is dropped for good).
  bool covered(const Cell& cell, const double* s) const {
    double w = width(), lo[N];
    for (int k = 0; k < N; ++k) lo[k] = double(cell.c[k]) * w;
    return far2(lo, w, s) < in2_;
  }

  // §4.2 Subdivide for every cell at once: children inside the disk of a sample that reaches
  // the parent (Appendix B, farthest corner) are pruned, the others become the new cells.
  // The samples that reach a level-0 cell are gathered once for all its descendants (they
  // are contiguous), then narrowed to those that reach each parent.
  void subdivide() {
    const double w = width(), h = 0.5 * w, base_w = 1.0 / double(res_);
    uint32_t base[N] = {Cell::kDead};
    cells_.subdivide([&](const Cell& parent, Cell* kids) {
      bool same = true;
      for (int k = 0; k < N; ++k) same &= (parent.c[k] >> level_) == base[k];
      if (!same) {
        double lo[N], centre[N];
        for (int k = 0; k < N; ++k) {
          base[k] = parent.c[k] >> level_;
          lo[k] = double(base[k]) * base_w;
          centre[k] = lo[k] + 0.5 * base_w;
        }
        base_count_ = 0;
        grid_.visit(centre, d_ + 0.5 * base_w, [&](const double* s, uint32_t id) {
          // Without branches: every sample is written, the count moves on for those that
          // reach (entries kMaxNear and on are scratch; the last one stays kNone).
          Near& at = base_near_[std::min(base_count_, kMaxNear)];
          std::copy(s, s + N, at.x);
          at.id = id;
          base_count_ += int(near2(lo, base_w, s) < d2_) & int(base_count_ < kMaxNear);
          return false;
        });
      }
      // Appendix B per axis: the offsets of a sample from the parent's three planes give the
      // nearest, farthest and centre distances of both halves; a child sums one half per axis.
      double lo[N];
      for (int k = 0; k < N; ++k) lo[k] = double(parent.c[k]) * w;
      if constexpr (N == 2) return split_2d(lo, w, kids);
      double best[Cells::kKids][Cell::kWitnesses];
      int best_at[Cells::kKids][Cell::kWitnesses];  // their entries in base_near_
      for (int j = 0; j < Cells::kKids; ++j) {
        std::fill(best[j], best[j] + Cell::kWitnesses, d2_);
        std::fill(best_at[j], best_at[j] + Cell::kWitnesses, -1);
        std::fill(kids[j].near, kids[j].near + Cell::kWitnesses, Cell::kNone);
      }
      uint32_t alive = ~uint32_t(0) >> (32 - Cells::kKids);
      for (int i = 0; i < base_count_ && alive != 0; ++i) {
        const double* s = base_near_[i].x;
        double parent_near = 0.0;
        for (int k = 0; k < N; ++k) {
          double e0 = s[k] - lo[k], e2 = e0 - w, pn = e0 < 0.0 ? e0 : e2 > 0.0 ? e2 : 0.0;
          parent_near += pn * pn;
        }
        if (parent_near >= d2_) continue;  // the disk misses the parent
        double nearest[N][2], farthest[N][2], centre[N][2], parent_far = 0.0;
        for (int k = 0; k < N; ++k) {
          double e0 = s[k] - lo[k], e1 = e0 - h, e2 = e1 - h;
          double a0 = std::abs(e0), a1 = std::abs(e1), a2 = std::abs(e2);
          farthest[k][0] = std::max(a0, a1) * std::max(a0, a1);
          farthest[k][1] = std::max(a1, a2) * std::max(a1, a2);
          double n0 = e0 < 0.0 ? e0 : e1 > 0.0 ? e1 : 0.0, n1 = e1 < 0.0 ? e1 : e2 > 0.0 ? e2 : 0.0;
          nearest[k][0] = n0 * n0;
          nearest[k][1] = n1 * n1;
          centre[k][0] = (e0 - 0.5 * h) * (e0 - 0.5 * h);
          centre[k][1] = (e1 - 0.5 * h) * (e1 - 0.5 * h);
          parent_far += std::max(a0, a2) * std::max(a0, a2);
        }
        if (parent_far < in2_) return 0u;  // the whole parent is covered
        for (int j = 0; j < Cells::kKids; ++j) {
          if (!(alive >> j & 1)) continue;
          double f = 0.0, n = 0.0, c = 0.0;
          for (int k = 0; k < N; ++k) {
            int half = (j >> k) & 1;
            f += farthest[k][half], n += nearest[k][half], c += centre[k][half];
          }
          if (f < in2_) {
            alive &= ~(uint32_t(1) << j);  // covered by one disk: pruned
            continue;
          }
          if (n >= d2_) continue;
          // Overlaps: a witness if it is among the disks that come closest to the centre.
          uint32_t id = base_near_[i].id;
          int at = i;
          for (int r = 0; r < Cell::kWitnesses; ++r)
            if (c < best[j][r]) std::swap(c, best[j][r]), std::swap(id, kids[j].near[r]), std::swap(at, best_at[j][r]);
        }
      }
      // 2-D: a child no single disk covers may lie in the union of its two witnesses.
      if constexpr (N == 2)
        for (uint32_t m = alive; m != 0; m &= m - 1) {
          const int j = std::countr_zero(m);
          if (best_at[j][1] < 0) continue;
          double clo[2];
          for (int k = 0; k < 2; ++k) clo[k] = lo[k] + ((j >> k) & 1) * h;
          if (square_in_two_disks(clo, h, base_near_[best_at[j][0]].x, base_near_[best_at[j][1]].x, in2_))
            alive &= ~(uint32_t(1) << j);
        }
      return alive;
    });
    ++level_;
    index_groups();
  }

  // The 2-D children of the parent at lo: the generic loop's per-axis terms, with selects
  // instead of branches (those mispredicted about 30 times per parent). A child is pruned
  // when one disk holds its four corners, or when its two witnesses do together
  // (two_disk_cover.h).
  uint32_t split_2d(const double* lo, double w, Cell* kids) {
    const double h = 0.5 * w, q = 0.25 * w;
    // A witness holds the child's centre; the two nearest it are kept. Key: the squared
    // distance's bits (monotone for doubles >= 0) with the low ones traded for the sample's
    // entry in base_near_ (kMaxNear: none).
    constexpr uint64_t kIndex = 2 * kMaxNear - 1, kNoWitness = ~uint64_t(0);
    uint64_t best[4][2];
    for (int j = 0; j < 4; ++j) best[j][0] = best[j][1] = kNoWitness;
    uint32_t single = 0;  // children inside one disk
    for (int i = 0; i < base_count_; ++i) {
      const double* s = base_near_[i].x;
      double far[2][3], c[2][2];  // per axis: squared offset from each plane; from each half's centre
      for (int k = 0; k < 2; ++k) {
        const double e0 = s[k] - lo[k], e1 = e0 - h, e2 = e1 - h;
        far[k][0] = e0 * e0, far[k][1] = e1 * e1, far[k][2] = e2 * e2;
        c[k][0] = (e0 - q) * (e0 - q), c[k][1] = (e1 - q) * (e1 - q);
      }
      for (int j = 0; j < 4; ++j) {
        const int jx = j & 1, jy = j >> 1;
        const double f = std::max(far[0][jx], far[0][jx + 1]) + std::max(far[1][jy], far[1][jy + 1]);
        single |= uint32_t(f < in2_) << j;
        const double cc = c[0][jx] + c[1][jy];
        const uint64_t key = (std::bit_cast<uint64_t>(cc) & ~kIndex) | uint64_t(i) | -uint64_t(!(cc < d2_));
        const uint64_t lower = best[j][0] < key ? best[j][0] : key, upper = best[j][0] < key ? key : best[j][0];
        best[j][0] = lower;
        best[j][1] = best[j][1] < upper ? best[j][1] : upper;
      }
    }
    uint32_t alive = ~single & 15u;
    for (int j = 0; j < 4; ++j)
      for (int r = 0; r < 2; ++r) kids[j].near[r] = base_near_[best[j][r] & kIndex].id;
    for (uint32_t m = alive; m != 0; m &= m - 1) {
      const int j = std::countr_zero(m);
      if (best[j][1] == kNoWitness) continue;
      const double clo[2] = {lo[0] + (j & 1) * h, lo[1] + (j >> 1) * h};
      if (square_in_two_disks(clo, h, base_near_[best[j][0] & kIndex].x, base_near_[best[j][1] & kIndex].x, in2_))
        alive &= ~(uint32_t(1) << j);
    }
    return alive;
  }

  double d_, d2_, in2_;
  bool periodic_;
  Rng rng_;
  Grid grid_;
  Cells cells_;
  uint32_t res_ = 1;  // cells per axis at level 0
  int level_ = 0, last_ = 0;
  std::vector<Pending> updates_[2];  // accepted samples whose Update waits (advance_updates())
  std::vector<uint32_t, HugePageAllocator<uint32_t>>
      group_;                     // per level-0 cell, the first slot of its cells (index_groups())
  bool groups_identity_ = false;  // group_[b] would be b (index_groups())
  // The samples reaching the level-0 cell; the entries from kMaxNear on name no sample.
  std::vector<Near> base_near_ = std::vector<Near>(2 * kMaxNear, Near{{}, Cell::kNone});
  int base_count_ = 0;
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
    case 1:
      ps.coords = sample<1>(dist, p.periodic, p.seed);
      break;
    case 2:
      ps.coords = sample<2>(dist, p.periodic, p.seed);
      break;
    case 3:
      ps.coords = sample<3>(dist, p.periodic, p.seed);
      break;
    case 4:
      ps.coords = sample<4>(dist, p.periodic, p.seed);
      break;
    default:
      ps.coords = sample<5>(dist, p.periodic, p.seed);
      break;
  }
  ps.radius.assign(ps.size(), dist);
  return ps;
}

}  // namespace pdrt
