// `bridson`: Bridson 2007, "Fast Poisson Disk Sampling in Arbitrary Dimensions". An active
// list grows from a random seed point; each active point tries k candidates drawn uniformly
// from the spherical annulus [r, 2r) around it and retires when all k fail. O(N).
// Candidates are drawn from the annulus directly (uniform direction, radius with density
// ~ rho^(n-1)), not by rejection from a 4^n box, which collapses in 4–5-D.
#include "generator.h"
#include "neighbor_grid.h"
#include "distance.h"
#include "rng.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace pdrt {
namespace {

// 2-D fast path. Background grid of cell side just under r/sqrt(2) (Bridson step 0: at most
// one point per cell), in cell units so a query is a 5x5 block around the candidate's cell.
// Each cell stores its point's offset from the cell corner as floats, x and y in separate
// arrays (empty cells: far away), so one row of the block is two unaligned 4-wide loads
// per axis; a float test with a small margin decides almost every candidate, and only
// distances within the margin of r are redone exactly in doubles. Small float offsets
// (not absolute coordinates) keep the float error ~1e-7 of a cell at any resolution.
// Ghost cells pad the grid so queries never bounds-check; periodic ghosts hold wrapped copies.
class Grid2D {
 public:
  using V4 = float __attribute__((vector_size(16)));
  using M4 = int32_t __attribute__((vector_size(16)));

  Grid2D(double r, bool periodic) : periodic_(periodic), r2_(r * r) {
    // Cells a hair narrower than r/sqrt(2) so rounding never puts two points in one cell;
    // r < 0.5 keeps 2 cells >= r, so the 5x5 block covers the disk of radius r.
    res_ = std::max(3, int(std::ceil(std::sqrt(2.0) / r * (1.0 + 1e-9))));
    scale_ = double(res_);
    stride_ = res_ + kPadLo + kPadHi;
    const std::size_t cells = std::size_t(stride_) * std::size_t(res_ + 2 * kPadLo);
    fx_.assign(cells, kFar);
    fy_.assign(cells, kFar);
    id_.assign(cells, -1);
    const double rc2 = r2_ * scale_ * scale_;
    // Float error of a squared cell-unit distance near r is < 1e-6 relative (see above).
    lo_ = float(rc2 * (1.0 - 1e-5));
    hi_ = float(rc2 * (1.0 + 1e-5));
  }

  // True when a stored point is closer than r to (x, y) in [0,1)^2 (toroidally if periodic).
  bool conflicts(double x, double y, const double* pts) const {
    const double u = x * scale_, v = y * scale_;
    const int cx = std::min(int(u), res_ - 1), cy = std::min(int(v), res_ - 1);
    const std::size_t c = index(cx, cy);
    // An occupied own cell is closer than its diagonal (< r): the commonest rejection.
    if (id_[c] >= 0) return true;
    const float fu = float(u - cx), fv = float(v - cy);
    // Columns cx-2 .. cx+5; the last three are >= 2 cells (> r) away and never hit.
    const V4 ax0 = V4{-2.f, -1.f, 0.f, 1.f} - fu, ax1 = V4{2.f, 3.f, 4.f, 5.f} - fu;
    const float* rx = &fx_[c - 2 - 2 * std::size_t(stride_)];
    const float* ry = &fy_[c - 2 - 2 * std::size_t(stride_)];
    auto row = [&](int dy) {
      const std::size_t o = std::size_t(dy + 2) * stride_;
      const float ay = float(dy) - fv;
      V4 x0 = load(rx + o) + ax0, x1 = load(rx + o + 4) + ax1;
      V4 y0 = load(ry + o) + ay, y1 = load(ry + o + 4) + ay;
      V4 d0 = x0 * x0 + y0 * y0, d1 = x1 * x1 + y1 * y1;
      return d0 < d1 ? d0 : d1;
    };
    // Nearest rows first: most rejected candidates stop after three rows.
    V4 m = min(row(0), min(row(-1), row(1)));
    if (any(m < lo_)) return true;
    m = min(m, min(row(-2), row(2)));
    if (any(m < lo_)) return true;
    if (!any(m < hi_)) return false;
    return exact(x, y, cx, cy, pts);
  }

  void insert(double x, double y, int32_t id) {
    const double u = x * scale_, v = y * scale_;
    const int cx = std::min(int(u), res_ - 1), cy = std::min(int(v), res_ - 1);
    const float fu = float(u - cx), fv = float(v - cy);
    put(cx, cy, fu, fv, id);
    if (!periodic_) return;
    // Ghost copies for neighbours across the wrap (same offset within the cell).
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        if (!ox && !oy) continue;
        int gx = cx + ox * res_, gy = cy + oy * res_;
        if (gx >= -kPadLo && gx < res_ + kPadLo && gy >= -kPadLo && gy < res_ + kPadLo) put(gx, gy, fu, fv, id);
      }
  }

 private:
  static constexpr int kPadLo = 2;  // ghost cells below / left (and above)
  static constexpr int kPadHi = 6;  // right: room for the 8-wide row loads
  static constexpr float kFar = 1e4f;

  static V4 load(const float* p) {
    V4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static V4 min(V4 a, V4 b) { return a < b ? a : b; }
  static bool any(M4 m) {
    uint64_t h[2];
    std::memcpy(h, &m, sizeof h);
    return (h[0] | h[1]) != 0;
  }

  // Distances within the float margin of r: decide in doubles, as the tests measure them.
  bool exact(double x, double y, int cx, int cy, const double* pts) const {
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int32_t i = id_[index(cx + dx, cy + dy)];
        if (i < 0) continue;
        const double ex = axis_delta(x, pts[2 * i], periodic_), ey = axis_delta(y, pts[2 * i + 1], periodic_);
        if (ex * ex + ey * ey < r2_) return true;
      }
    return false;
  }

  std::size_t index(int cx, int cy) const { return std::size_t(cy + kPadLo) * stride_ + std::size_t(cx + kPadLo); }
  void put(int cx, int cy, float fu, float fv, int32_t id) {
    const std::size_t c = index(cx, cy);
    fx_[c] = fu;
    fy_[c] = fv;
    id_[c] = id;
  }

  bool periodic_;
  double r2_, scale_;
  int res_, stride_;
  float lo_, hi_;
  std::vector<float> fx_, fy_;
  std::vector<int32_t> id_;
};

PointSet bridson_2d(const GeneratorParams& p, double r, std::size_t limit) {
  const int k = int(p.attempts.value_or(30));
  Grid2D grid(r, p.periodic);
  Rng rng(p.seed, 0x62726964);
  PointSet ps;
  ps.dim = 2;
  struct Active {
    double x, y;
  };
  std::vector<Active> active;  // coordinates, not indices: no random access into ps
  ps.coords.reserve(2 * std::size_t(std::min<double>(double(limit), expected_count_for_radius(r, 2) * 1.3)));
  auto add = [&](double x, double y) {
    grid.insert(x, y, int32_t(ps.size()));
    active.push_back({x, y});
    ps.coords.push_back(x);
    ps.coords.push_back(y);
  };
  add(rng.uniform(), rng.uniform());
  // Offsets in units of 2r / 2^31: a 32-bit half of a draw is one coordinate in [-2r, 2r).
  const double unit = r * 0x1.0p-30;
  while (!active.empty() && ps.size() < limit) {
    const std::size_t slot = rng.below(active.size());
    const double px = active[slot].x, py = active[slot].y;
    bool found = false;
    for (int t = 0; t < k; ++t) {
      // Uniform in the annulus [r, 2r) by rejection from its bounding square (acceptance
      // 3*pi/16), one 64-bit draw per try; the ring test is exact integer arithmetic.
      int64_t a, b;
      for (;;) {
        const uint64_t w = rng.next_u64();
        a = int32_t(uint32_t(w));
        b = int32_t(uint32_t(w >> 32));
        if (uint64_t(a * a + b * b) - (uint64_t(1) << 60) < (uint64_t(3) << 60)) break;
      }
      double x = px + double(a) * unit, y = py + double(b) * unit;
      if (p.periodic) {
        x -= std::floor(x);
        y -= std::floor(y);
        if (x >= 1.0) x = 0.0;
        if (y >= 1.0) y = 0.0;
      } else if (x < 0.0 || x >= 1.0 || y < 0.0 || y >= 1.0) {
        continue;
      }
      if (grid.conflicts(x, y, ps.coords.data())) continue;
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
