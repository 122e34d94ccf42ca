// `bridson`: Bridson 2007, "Fast Poisson Disk Sampling in Arbitrary Dimensions". An active
// list grows from a random seed point; each active point tries k candidates drawn uniformly
// from the spherical annulus [r, 2r) around it and retires when all k fail. O(N).
// Candidates are drawn from the annulus directly (uniform direction, radius with density
// ~ rho^(n-1)), not by rejection from a 4^n box, which collapses in 4–5-D.
#include "generator.h"
#include "neighbor_grid.h"
#include "rng.h"

#include <cmath>
#include <vector>

namespace pdrt {
namespace {

// 2-D fast path: background grid of cell side r/sqrt(2) holds at most one point per cell
// (Bridson step 0), padded by two ghost cells per side so a query never bounds-checks. In
// periodic mode the ghost cells hold wrapped copies.
class Grid2D {
 public:
  Grid2D(double r, bool periodic) : periodic_(periodic) {
    res_ = std::max(1, int(std::ceil(std::sqrt(2.0) / r)));
    inv_cell_ = double(res_);
    stride_ = res_ + 2 * kPad;
    cells_.assign(std::size_t(stride_) * stride_, Cell{kEmpty, kEmpty});
  }

  bool conflicts(double x, double y, double r2) const {
    int cx = int(x * inv_cell_) + kPad, cy = int(y * inv_cell_) + kPad;
    const Cell* row = &cells_[std::size_t(cy - 2) * stride_ + cx];
    // The 5x5 block holds every point closer than r (cells are just under r/sqrt(2) wide,
    // so the corners can too).
    for (int dy = -2; dy <= 2; ++dy, row += stride_) {
      for (int dx = -2; dx <= 2; ++dx) {
        const Cell& c = row[dx];
        double ex = c.x - x, ey = c.y - y;
        if (ex * ex + ey * ey < r2) return true;
      }
    }
    return false;
  }

  void insert(double x, double y) {
    int cx = int(x * inv_cell_), cy = int(y * inv_cell_);
    put(cx, cy, x, y);
    if (!periodic_) return;
    // Ghost copies for neighbours across the wrap.
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        if (!ox && !oy) continue;
        int gx = cx + ox * res_, gy = cy + oy * res_;
        if (gx >= -kPad && gx < res_ + kPad && gy >= -kPad && gy < res_ + kPad) put(gx, gy, x + ox, y + oy);
      }
  }

 private:
  struct Cell {
    double x, y;
  };
  static constexpr int kPad = 2;
  static constexpr double kEmpty = -1e30;  // far from everything: never conflicts
  void put(int cx, int cy, double x, double y) { cells_[std::size_t(cy + kPad) * stride_ + cx + kPad] = Cell{x, y}; }

  bool periodic_;
  int res_, stride_;
  double inv_cell_;
  std::vector<Cell> cells_;
};

PointSet bridson_2d(const GeneratorParams& p, double r, std::size_t limit) {
  const int k = int(p.attempts.value_or(30));
  const double r2 = r * r, four_r2 = 4.0 * r2;
  Grid2D grid(r, p.periodic);
  Rng rng(p.seed, 0x62726964);
  PointSet ps;
  ps.dim = 2;
  std::vector<uint32_t> active;
  ps.coords.reserve(2 * std::size_t(std::min<double>(double(limit), expected_count_for_radius(r, 2) * 1.3)));
  auto add = [&](double x, double y) {
    active.push_back(uint32_t(ps.size()));
    ps.coords.push_back(x);
    ps.coords.push_back(y);
    grid.insert(x, y);
  };
  add(rng.uniform(), rng.uniform());
  while (!active.empty() && ps.size() < limit) {
    std::size_t slot = rng.below(active.size());
    const double px = ps.coords[2 * active[slot]], py = ps.coords[2 * active[slot] + 1];
    bool found = false;
    for (int t = 0; t < k; ++t) {
      // Uniform in the annulus by rejection from its bounding square (acceptance 3*pi/16),
      // cheaper than a sin/cos pair per candidate.
      double dx, dy, d2;
      do {
        dx = (4.0 * rng.uniform() - 2.0) * r;
        dy = (4.0 * rng.uniform() - 2.0) * r;
        d2 = dx * dx + dy * dy;
      } while (d2 < r2 || d2 >= four_r2);
      double x = px + dx, y = py + dy;
      if (p.periodic) {
        x -= std::floor(x);
        y -= std::floor(y);
        if (x >= 1.0) x = 0.0;
        if (y >= 1.0) y = 0.0;
      } else if (x < 0.0 || x >= 1.0 || y < 0.0 || y >= 1.0) {
        continue;
      }
      if (grid.conflicts(x, y, r2)) continue;
      add(x, y);
      found = true;
      break;
    }
    if (!found) {
      active[slot] = active.back();
      active.pop_back();
    }
  }
  return ps;
}

// Any dimension: uniform direction from normal deviates, radius r * (1 + u (2^n - 1))^(1/n)
// so the density in the annulus is uniform in volume.
PointSet bridson_nd(const GeneratorParams& p, double r, std::size_t limit) {
  const int dim = p.dim, k = int(p.attempts.value_or(30));
  const double r2 = r * r, shell = std::pow(2.0, dim) - 1.0;
  NeighborGrid grid(dim, p.periodic, r, std::size_t(expected_count_for_radius(r, dim)));
  Rng rng(p.seed, 0x62726964);
  PointSet ps;
  ps.dim = dim;
  std::vector<uint32_t> active;
  double x[kMaxDim], dir[kMaxDim];
  auto add = [&](const double* q) {
    active.push_back(uint32_t(ps.size()));
    grid.insert(uint32_t(ps.size()), q);
    ps.coords.insert(ps.coords.end(), q, q + dim);
  };
  for (int d = 0; d < dim; ++d) x[d] = rng.uniform();
  add(x);
  while (!active.empty() && ps.size() < limit) {
    std::size_t slot = rng.below(active.size());
    const std::size_t base = std::size_t(active[slot]) * dim;
    bool found = false;
    for (int t = 0; t < k && !found; ++t) {
      double norm2 = 0.0;
      do {
        norm2 = 0.0;
        for (int d = 0; d < dim; ++d) {
          dir[d] = rng.normal();
          norm2 += dir[d] * dir[d];
        }
      } while (norm2 < 1e-300);
      double rho = r * std::pow(1.0 + rng.uniform() * shell, 1.0 / dim) / std::sqrt(norm2);
      bool inside = true;
      for (int d = 0; d < dim; ++d) {
        double v = ps.coords[base + d] + dir[d] * rho;
        if (p.periodic) {
          v -= std::floor(v);
          if (v >= 1.0) v = 0.0;
        } else if (v < 0.0 || v >= 1.0) {
          inside = false;
        }
        x[d] = v;
      }
      if (!inside || grid.any_closer(x, r2)) continue;
      add(x);
      found = true;
    }
    if (!found) {
      active[slot] = active.back();
      active.pop_back();
    }
  }
  return ps;
}

}  // namespace

PointSet generate_bridson(const GeneratorParams& p) {
  const double r = p.radius ? *p.radius : radius_for_count(*p.count, p.dim, p.periodic);
  const std::size_t limit = p.count ? std::size_t(*p.count) : std::size_t(-1);
  // The padded 2-D grid needs r < 0.5 (at least 3 cells per axis, neighbours within 2 cells).
  PointSet ps = (p.dim == 2 && r < 0.5) ? bridson_2d(p, r, limit) : bridson_nd(p, r, limit);
  ps.radius.assign(ps.size(), r);
  return ps;
}

}  // namespace pdrt
