// `mccool`: McCool & Fiume 1992 §4 relaxation dart throwing. The minimum distance starts at
// `start_radius`; darts are thrown at it until `attempts + magnification * placed` darts in a
// row have missed, then the radius is multiplied by `decay`. Points are output in rank order
// with the (non-increasing) radius in force when each was placed, so every prefix is
// Poisson-disk at its own last radius, and the run ends with exactly `count` points.
//
// Speed without changing the process: darts that would land in space already covered are
// skipped in bulk. We keep cells that may still hold a point (grid of side r/sqrt(n), halved
// as darts fail, covered children dropped, as in Gamito–Maddock §4.2); the number of uniform
// darts up to the first one inside those cells is geometric in their total volume, and that
// dart is uniform inside them. So each step costs O(free cells), not O(attempts), and the
// paper's large attempt counts stay cheap. (The paper's "best-fitting rejected dart" shortcut
// only saved darts; with bulk skipping it is not needed.) 2-D, the tables' case, has its own
// flat grid (point_grid_2d.h) and tests sibling cells four at a time, with the same
// floating-point tests, so its output is bit-identical to the generic path's.
#include "sampling/generators/generator.h"
#include "sampling/generators/detail/neighbor_grid.h"
#include "sampling/generators/detail/point_grid_2d.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pdrt {
namespace {

struct Cell {
  uint32_t idx[kMaxDim];  // integer cell coordinates at the current level
};

class Relaxation {
 public:
  Relaxation(const GeneratorParams& p)
      : p_(p),
        dim_(p.dim),
        n_(*p.count),
        grid_(p.dim, p.periodic, 1.0, std::size_t(*p.count)),
        grid2_(p.periodic),
        rng_(p.seed, 0x6d63636f),
        attempts_(double(p.attempts.value_or(30))),
        magnification_(p.magnification.value_or(128.0)) {
    ps_.dim = dim_;
    ps_.coords.reserve(std::size_t(n_) * dim_);
    ps_.radius.reserve(std::size_t(n_));
  }

  PointSet run() {
    const double diameter = std::sqrt(double(dim_)) * (p_.periodic ? 0.5 : 1.0);
    const double decay = p_.decay.value_or(0.97);
    double r = std::min(p_.start_radius.value_or(default_start_radius(decay)), diameter);
    while (done() == false) {
      fill(r);
      r *= decay;
    }
    return std::move(ps_);
  }

 private:
  bool done() const { return int64_t(ps_.size()) >= n_; }

  // Like the paper's 0.3 for 64 points: large enough that the first 16 points are spread at
  // rho > 1 (a smaller start crowds the first prefixes), not so large that the first points
  // lock into a lattice. It is then lowered by less than one decay step so that a radius
  // step lands at 97% of the maximal-set radius for `count` (Gamito–Maddock Table I): the
  // run then ends near a full step, where rho is highest, instead of just after one.
  double default_start_radius(double decay) const {
    const double first = 1.1 * max_packing_distance(16, dim_);
    const double rho_end = 0.97 * std::pow(maximal_packing_density(dim_) / densest_packing_density(dim_), 1.0 / dim_);
    double r = rho_end * max_packing_distance(n_, dim_);
    while (r < first) r /= decay;
    return r;
  }

  void place(const double* x, double r) {
    if (dim_ == 2)
      grid2_.insert(x[0], x[1]);
    else
      grid_.insert(uint32_t(ps_.size()), x);
    ps_.coords.insert(ps_.coords.end(), x, x + dim_);
    ps_.radius.push_back(r);
    misses_ = 0;
  }

  // McCool §4: consecutive misses allowed at one radius, growing with the points placed.
  double budget() const { return attempts_ + magnification_ * double(ps_.size()); }

  // Uniform darts thrown up to and including the first inside `cells` cells of volume
  // `cell_volume` (geometric). log(1 - v) is cached: the cell count changes far less often
  // than darts are thrown.
  double darts_to_hit(std::size_t cells, double cell_volume) {
    double v = double(cells) * cell_volume;
    if (v >= 1.0) return 1.0;
    if (cells != log_cells_ || cell_volume != log_volume_)
      log_cells_ = cells, log_volume_ = cell_volume, log_miss_ = std::log1p(-v);
    double u = 1.0 - rng_.uniform();  // (0, 1]
    return 1.0 + std::floor(std::log(u) / log_miss_);
  }

  // Adds points at minimum distance r until the domain is full (or count is reached).
  void fill(double r) {
    if (dim_ == 2 && grid2_.resolution() != PointGrid2D::cells_for(r)) {
      grid2_.reset(r);  // cells as small as r allows: fewer points per query
      for (std::size_t i = 0; i < ps_.size(); ++i) grid2_.insert(ps_.coords[2 * i], ps_.coords[2 * i + 1]);
    } else if (dim_ != 2 && (r < 0.8 * grid_.reach() || grid_.reach() < r)) {
      grid_.reset(r, std::size_t(n_));
      for (std::size_t i = 0; i < ps_.size(); ++i) grid_.insert(uint32_t(i), ps_.coords.data() + i * dim_);
    }
    const double r2 = r * r;
    r_ = r;
    // In 1-D/2-D, cells of side r/sqrt(n) hold at most one point and an occupied cell is
    // covered. Above that such cells outnumber the points (54 per point in 5-D), so start
    // from cells of side r and let refinement do the rest.
    const bool fine = dim_ <= 2;
    int m = std::max(1, int(std::ceil((fine ? std::sqrt(double(dim_)) : 1.0) / r)));
    double cells = std::pow(double(m), dim_);
    misses_ = 0;
    if (cells > 64.0 * double(n_) + 4096.0) {
      // A fine grid would dwarf the point count (high dimension, early steps): plain darts.
      double x[kMaxDim];
      while (!done() && misses_ < budget()) {
        for (int k = 0; k < dim_; ++k) x[k] = rng_.uniform();
        if (any_closer(x, r2))
          ++misses_;
        else
          place(x, r);
      }
      return;
    }
    // Level-0 cells: every cell not already holding a point (cell diagonal <= r).
    // Member buffers, reused across radius steps (no reallocation per step).
    std::vector<Cell>& active = active_;
    std::vector<char>& occupied = occupied_;
    active.clear();
    occupied.assign(std::size_t(cells), 0);
    if (fine)
      for (std::size_t i = 0; i < ps_.size(); ++i) occupied[flat(ps_.coords.data() + i * dim_, m)] = 1;
    double side = 1.0 / m;
    if (dim_ == 2) mark_covered_2d(occupied, m, r2);
    for (std::size_t c = 0; c < occupied.size(); ++c) {
      if (occupied[c]) continue;
      Cell cell;
      std::size_t rest = c;
      for (int k = 0; k < dim_; ++k) cell.idx[k] = uint32_t(rest % m), rest /= m;
      // The domain was full at the previous radius, so most cells are still covered. Above
      // 3-D the 3^n-cell coverage query costs more than the darts it saves.
      if (dim_ == 2 || dim_ > 3 || !covered(cell, side, r2)) active.push_back(cell);
    }
    // Refinement shrinks the free area geometrically per level (Ebeida et al. 2011); seven
    // levels in 2-D leave only slivers, which the next, slightly smaller radius picks up.
    // Above 2-D a child is seldom inside a single disk, so children multiply by up to 2^n
    // per level: refine less and let the next radius step pick up the rest.
    const int levels = fine ? 7 : (dim_ == 3 ? 2 : 1);
    for (int level = 0; level < levels && !active.empty() && !done(); ++level) {
      double x[kMaxDim];
      const double cell_volume = std::pow(side, dim_);
      // Refine once the darts missed about twice per cell at this level.
      for (int64_t fails = 0; !active.empty() && !done() && fails < 2 * int64_t(active.size());) {
        misses_ += darts_to_hit(active.size(), cell_volume) - 1;
        if (misses_ >= budget()) return;  // McCool §4: no space found in time, shrink the radius
        std::size_t a = rng_.below(active.size());
        for (int k = 0; k < dim_; ++k) x[k] = (active[a].idx[k] + rng_.uniform()) * side;
        if (any_closer(x, r2)) {
          ++fails;
          if (++misses_ >= budget()) return;
          continue;
        }
        place(x, r);
        active[a] = active.back();  // the cell is now covered by the new point
        active.pop_back();
      }
      // Halve every remaining cell; keep children no disk covers entirely.
      std::vector<Cell>& next = next_;
      next.clear();
      double half = side / 2.0;
      for (const Cell& c : active) {
        if (dim_ == 2) {
          const unsigned kept = ~covered_quad(c.idx[0] * 2, c.idx[1] * 2, half, 0xfu, r2);
          for (unsigned b = 0; b < 4; ++b)
            if (kept >> b & 1) next.push_back(Cell{{2 * c.idx[0] + (b & 1), 2 * c.idx[1] + (b >> 1)}});
          continue;
        }
        for (int child = 0; child < (1 << dim_); ++child) {
          Cell ch;
          for (int k = 0; k < dim_; ++k) ch.idx[k] = 2 * c.idx[k] + ((child >> k) & 1);
          if (!covered(ch, half, r2)) next.push_back(ch);
        }
      }
      active.swap(next);
      side = half;
    }
  }

  std::size_t flat(const double* x, int m) const {
    std::size_t idx = 0;
    for (int k = dim_ - 1; k >= 0; --k) idx = idx * m + std::size_t(std::min(int(x[k] * m), m - 1));
    return idx;
  }

  // True when a point is closer than sqrt(r2) to x (McCool §4's dart test).
  bool any_closer(const double* x, double r2) const {
    if (dim_ != 2) return grid_.any_closer(x, r2);
    return any_near_2d(x[0], x[1], r_, [&](double ex, double ey, const double*) { return ex * ex + ey * ey < r2; });
  }

  // f(ex, ey, q) with (ex, ey) = (x, y) - q wrapped, for every point q within `reach` (and
  // some farther) until f returns true: the grid's box, or a scan of every point while the
  // grid is too coarse for it (the first few dozen points). The differences are
  // axis_delta's either way.
  template <class F>
  [[gnu::always_inline]] bool any_near_2d(double x, double y, double reach, F&& f) const {
    if (grid2_.resolution() >= PointGrid2D::kMinCells)
      return grid2_.any_in_box(x - reach, x + reach, y - reach, y + reach, [&](const double* q, double sx, double sy) {
        return f((x - q[0]) + sx, (y - q[1]) + sy, q);
      });
    for (std::size_t i = 0; i < ps_.size(); ++i) {
      const double* q = ps_.coords.data() + 2 * i;
      if (f(axis_delta(x, q[0], p_.periodic), axis_delta(y, q[1], p_.periodic), q)) return true;
    }
    return false;
  }

  // covered()'s test in 2-D for a point at difference (ex, ey) from the centre of a cell of
  // half-side h: the same expression (|x - q| = |q - x| bit for bit, so the grid's
  // differences serve), after the cheaper centre-distance test.
  static bool covers_2d(double ex, double ey, double h, double r2) {
    if (ex * ex + ey * ey >= r2) return false;
    const double dx = std::abs(ex) + h, dy = std::abs(ey) + h;
    return dx * dx + dy * dy < r2;
  }

  // covered() in 2-D, one cell.
  bool covered_2d(const Cell& c, double side, double r2) {
    const double x = (c.idx[0] + 0.5) * side, y = (c.idx[1] + 0.5) * side, h = side / 2.0;
    return any_near_2d(x, y, r_, [&](double ex, double ey, const double*) { return covers_2d(ex, ey, h, r2); });
  }

  // 2-D level 0: marks the free cells (0 in `state`, m x m of side 1/m) that one disk
  // covers, 2x2 cells at a time, so that the caller lists the rest in raster order.
  void mark_covered_2d(std::vector<char>& state, int m, double r2) {
    const double side = 1.0 / m;
    for (int y = 0; y < m; y += 2)
      for (int x = 0; x < m; x += 2) {
        unsigned want = 0;
        for (unsigned b = 0; b < 4; ++b) {
          const int cx = x + int(b & 1), cy = y + int(b >> 1);
          if (cx < m && cy < m && !state[std::size_t(cy) * m + cx]) want |= 1u << b;
        }
        if (!want) continue;
        const unsigned got = covered_quad(uint32_t(x), uint32_t(y), side, want, r2);
        for (unsigned b = 0; b < 4; ++b)
          if (got >> b & 1) state[std::size_t(y + (b >> 1)) * m + x + (b & 1)] = 2;
      }
  }

  // covered_2d for the 2x2 cells of side `side` with corner cell (ix, iy), only those in
  // `want`: bit bx + 2 by set when cell (ix + bx, iy + by) is covered. One walk over the
  // grid cells near the quad tests all four (the same tests, in another order).
  unsigned covered_quad(uint32_t ix, uint32_t iy, double side, unsigned want, double r2) {
    const double xs[2] = {(ix + 0.5) * side, (ix + 1 + 0.5) * side}, ys[2] = {(iy + 0.5) * side, (iy + 1 + 0.5) * side};
    const double h = side / 2.0;
    unsigned got = 0;
    if (grid2_.resolution() < PointGrid2D::kMinCells) {
      for (unsigned b = 0; b < 4; ++b)
        if ((want & ~got) >> b & 1 && covered_2d(Cell{{ix + (b & 1), iy + (b >> 1)}}, side, r2)) got |= 1u << b;
      return got;
    }
    // A point whose disk holds a cell is within r - h of its centre (the far corner is at
    // least h farther): within r of the quad's centre (px, py) on each axis, and within
    // r - h + h sqrt(2) < r + h/2 of it, a cheap test that drops most of the box.
    const double px = (ix + 1) * side, py = (iy + 1) * side, lim = r_ + h / 2, near2 = lim * lim;
    grid2_.any_in_box(px - r_, px + r_, py - r_, py + r_, [&](const double* q, double sx, double sy) {
      const double gx = (px - q[0]) + sx, gy = (py - q[1]) + sy;
      if (gx * gx + gy * gy > near2) return false;
      const double ex[2] = {(xs[0] - q[0]) + sx, (xs[1] - q[0]) + sx},
                   ey[2] = {(ys[0] - q[1]) + sy, (ys[1] - q[1]) + sy};
      for (unsigned b = 0; b < 4; ++b) {
        if (!((want & ~got) >> b & 1)) continue;
        if (covers_2d(ex[b & 1], ey[b >> 1], h, r2)) got |= 1u << b;
      }
      return got == want;
    });
    return got;
  }

  // True when one point's disk contains the whole cell (its farthest corner is within r).
  // Neighbouring cells are usually covered by the same point, so the last one found is
  // tried first. (2-D has covered_quad.)
  bool covered(const Cell& c, double side, double r2) {
    double centre[kMaxDim];
    for (int k = 0; k < dim_; ++k) centre[k] = (c.idx[k] + 0.5) * side;
    auto covers = [&](const double* q) {
      double far2 = 0.0;
      for (int k = 0; k < dim_; ++k) {
        double d = std::abs(axis_delta(q[k], centre[k], p_.periodic)) + side / 2.0;
        far2 += d * d;
      }
      return far2 < r2;
    };
    if (hint_ < ps_.size() && covers(ps_.coords.data() + hint_ * dim_)) return true;
    return grid_.visit_near(centre, [&](uint32_t id, const double* q, double d2) {
      if (d2 >= r2 || !covers(q)) return false;  // a point farther than r from the centre cannot cover
      hint_ = id;
      return true;
    });
  }

  const GeneratorParams& p_;
  int dim_;
  int64_t n_;
  NeighborGrid grid_;  // neighbour search in 1-D and 3-D and up
  PointGrid2D grid2_;  // and in 2-D
  Rng rng_;
  PointSet ps_;
  double attempts_, magnification_;
  double misses_ = 0;  // consecutive missed darts at the current radius
  std::size_t log_cells_ = 0;
  double log_volume_ = 0.0, log_miss_ = 0.0;  // darts_to_hit's cache of log(1 - v)
  double r_ = 0.0;                            // the radius of the current step
  std::vector<Cell> active_, next_;           // fill()'s free cells at this and the next level
  std::vector<char> occupied_;                // fill()'s level-0 cells: 1 holds a point, 2 covered
  std::size_t hint_ = 0;                      // index of the point that covered the last cell
};

}  // namespace

PointSet generate_mccool(const GeneratorParams& p) { return Relaxation(p).run(); }

}  // namespace pdrt
