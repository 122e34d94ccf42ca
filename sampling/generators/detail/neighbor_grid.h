#pragma once
// Uniform n-D grid over [0,1)^dim for fixed-radius neighbour queries. Cells are at least
// `reach` wide, so every point within `reach` of a query lies in the 3^dim block of cells
// around it (wrapped when periodic). Points are copied in so queries stay cache-local.
#include "sampling/core/distance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pdrt {

class NeighborGrid {
 public:
  NeighborGrid(int dim, bool periodic, double reach, std::size_t expected_points) : dim_(dim), periodic_(periodic) {
    reset(reach, expected_points);
  }

  // Clears the grid and sets a new reach (cell size >= reach).
  void reset(double reach, std::size_t expected_points) {
    reach_ = reach;
    int m = reach > 0.0 ? int(std::floor(1.0 / reach)) : 1;
    m = std::max(m, 1);
    // Keep the cell count proportional to the points so sparse high-dim grids stay small.
    double cap = std::max<double>(1024.0, 4.0 * double(expected_points));
    while (m > 1 && std::pow(double(m), dim_) > cap) --m;
    res_ = m;
    std::size_t cells = 1;
    for (int k = 0; k < dim_; ++k) cells *= std::size_t(res_);
    head_.assign(cells, -1);
    next_.clear();
    pts_.clear();
    ids_.clear();
  }

  double reach() const { return reach_; }
  std::size_t size() const { return ids_.size(); }

  void insert(uint32_t id, const double* p) {
    std::size_t c = cell_of(p);
    int32_t slot = int32_t(ids_.size());
    ids_.push_back(id);
    pts_.insert(pts_.end(), p, p + dim_);
    next_.push_back(head_[c]);
    head_[c] = slot;
  }

  // Calls f(id, coords, dist_sq) for stored points within the 3^dim cell block around p
  // (a superset of those within reach). Stops early when f returns true; returns whether it did.
  template <class F>
  bool visit_near(const double* p, F&& f) const {
    if (dim_ == 2 && res_ >= 3) return visit_near_2d(p, f);
    int lo[16], hi[16], cur[16];
    for (int k = 0; k < dim_; ++k) {
      int c = axis_cell(p[k]);
      if (res_ <= 2) {
        lo[k] = 0, hi[k] = res_ - 1;
      } else if (periodic_) {
        lo[k] = c - 1, hi[k] = c + 1;
      } else {
        lo[k] = std::max(c - 1, 0), hi[k] = std::min(c + 1, res_ - 1);
      }
      cur[k] = lo[k];
    }
    for (;;) {
      std::size_t idx = 0;
      for (int k = dim_ - 1; k >= 0; --k) {
        int c = cur[k];
        if (c < 0) c += res_;
        if (c >= res_) c -= res_;
        idx = idx * std::size_t(res_) + std::size_t(c);
      }
      for (int32_t s = head_[idx]; s >= 0; s = next_[s]) {
        const double* q = &pts_[std::size_t(s) * dim_];
        if (f(ids_[s], q, distance_sq(p, q, dim_, periodic_))) return true;
      }
      int k = 0;
      while (k < dim_ && cur[k] == hi[k]) cur[k] = lo[k], ++k;
      if (k == dim_) return false;
      ++cur[k];
    }
  }

  // True when some stored point is closer than sqrt(r2) (r2 <= reach^2).
  bool any_closer(const double* p, double r2) const {
    return visit_near(p, [&](uint32_t, const double*, double d2) { return d2 < r2; });
  }

  // Smallest squared distance to a stored point, looking no farther than `reach`;
  // returns `limit2` when none is closer.
  double nearest_sq(const double* p, double limit2) const {
    double best = limit2;
    visit_near(p, [&](uint32_t, const double*, double d2) {
      best = std::min(best, d2);
      return false;
    });
    return best;
  }

 private:
  // The common 2-D case without the odometer (this is the hot loop of the generators).
  template <class F>
  bool visit_near_2d(const double* p, F& f) const {
    const int cx = axis_cell(p[0]), cy = axis_cell(p[1]);
    for (int dy = -1; dy <= 1; ++dy) {
      int y = cy + dy;
      if (y < 0 || y >= res_) {
        if (!periodic_) continue;
        y = y < 0 ? y + res_ : y - res_;
      }
      for (int dx = -1; dx <= 1; ++dx) {
        int x = cx + dx;
        if (x < 0 || x >= res_) {
          if (!periodic_) continue;
          x = x < 0 ? x + res_ : x - res_;
        }
        for (int32_t s = head_[std::size_t(y) * res_ + x]; s >= 0; s = next_[s]) {
          const double* q = &pts_[std::size_t(s) * 2];
          double ex = axis_delta(p[0], q[0], periodic_), ey = axis_delta(p[1], q[1], periodic_);
          if (f(ids_[s], q, ex * ex + ey * ey)) return true;
        }
      }
    }
    return false;
  }

  int axis_cell(double x) const { return std::clamp(int(x * res_), 0, res_ - 1); }
  std::size_t cell_of(const double* p) const {
    std::size_t idx = 0;
    for (int k = dim_ - 1; k >= 0; --k) idx = idx * std::size_t(res_) + std::size_t(axis_cell(p[k]));
    return idx;
  }

  int dim_;
  bool periodic_;
  double reach_ = 0.0;
  int res_ = 1;
  std::vector<int32_t> head_, next_;
  std::vector<double> pts_;
  std::vector<uint32_t> ids_;
};

}  // namespace pdrt
