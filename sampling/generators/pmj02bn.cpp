// `pmj02bn` (pmj02bn.h): Christensen et al.'s progressive multi-jittered (0,2) construction
// with best-candidate selection, valid strata found as in Pharr 2019.
#include "sampling/generators/pmj02bn.h"

#include "sampling/core/errors.h"
#include "sampling/core/fixed_point.h"
#include "sampling/core/rng.h"
#include "sampling/generators/generator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace pdrt {
namespace {

class Builder {
 public:
  Builder(int64_t count, uint64_t seed, int candidates)
      : count_(count), candidates_(candidates), rng_(seed, 0x706d6a3032626eull) {  // "pmj02bn"
    xy_.reserve(std::size_t(2 * count));
    radius_.reserve(std::size_t(count));
  }

  void run() {
    const uint64_t first = rng_.next_u64();
    set_grid(1);
    add(uint32_t(first), uint32_t(first >> 32));
    // n = 4^k points so far: each lies alone in its square of side 2^-k.
    for (int k = 0; size() < count_; ++k) {
      const uint32_t n = uint32_t(1) << (2 * k);
      const int d = k + 1;  // the sub-squares' bits per axis
      set_grid(d);
      // Second quarter (level 2k + 1): the sub-square diagonally opposite each earlier point.
      set_level(2 * k + 1);
      const std::vector<uint32_t> order = shuffled(n);
      for (uint32_t i = 0; i < n && size() < count_; ++i) {
        const auto [qx, qy] = sub_square(order[i], d);
        place(d, {qx ^ 1u, qy ^ 1u});
      }
      // Third quarter (level 2k + 2): one of the two sub-squares left in each 2^-k square, the
      // one the best candidate falls in; the fourth quarter takes the other, in the same order.
      set_level(2 * k + 2);
      const std::vector<uint32_t> order3 = shuffled(n);
      std::vector<std::pair<uint32_t, uint32_t>> third(n);
      for (uint32_t i = 0; i < n && size() < count_; ++i) {
        const auto [qx, qy] = sub_square(order3[i], d);
        place(d, {qx ^ 1u, qy}, Square{qx, qy ^ 1u});
        third[i] = sub_square(uint32_t(size() - 1), d);
      }
      for (uint32_t i = 0; i < n && size() < count_; ++i) place(d, {third[i].first ^ 1u, third[i].second ^ 1u});
    }
  }

  std::vector<uint32_t> take_xy() { return std::move(xy_); }
  std::vector<double> take_radius() { return std::move(radius_); }

 private:
  using Square = std::pair<uint32_t, uint32_t>;

  int64_t size() const { return int64_t(xy_.size() / 2); }

  Square sub_square(uint32_t i, int d) const {
    return {fixed_top_bits(xy_[2 * i], d), fixed_top_bits(xy_[2 * i + 1], d)};
  }

  std::vector<uint32_t> shuffled(uint32_t n) {
    std::vector<uint32_t> v(n);
    std::iota(v.begin(), v.end(), 0u);
    for (uint32_t i = n; i > 1; --i) std::swap(v[i - 1], v[rng_.below(i)]);
    return v;
  }

  // Occupancy of the elementary intervals of level L: shape a has a bits of x and L - a of y.
  void set_level(int L) {
    L_ = L;
    occ_.assign(std::size_t(L + 1) << L, 0);
    for (int64_t i = 0; i < size(); ++i) mark(xy_[2 * i], xy_[2 * i + 1]);
  }
  std::size_t interval(int a, uint32_t xbits, uint32_t ybits) const {
    return (std::size_t(a) << L_) | (std::size_t(xbits) << (L_ - a)) | ybits;
  }
  void mark(uint32_t X, uint32_t Y) {
    for (int a = 0; a <= L_; ++a) occ_[interval(a, fixed_top_bits(X, a), fixed_top_bits(Y, L_ - a))] = 1;
  }

  // The L-bit strata of `axis` (0: x, 1: y) in sub-square (qx, qy) (d bits each) that leave
  // every interval with more than d bits on that axis empty. The other axis has fewer than d bits
  // in such a shape, which the sub-square fixes, so the x and the y choices are independent
  // (Pharr 2019). Grown one bit at a time, dropping the children whose interval is taken.
  void valid_strata(int axis, uint32_t qx, uint32_t qy, int d, std::vector<uint32_t>& out) const {
    out.assign(1, axis ? qy : qx);
    for (int bits = d + 1; bits <= L_; ++bits) {
      const int other = L_ - bits;
      const uint32_t fixed = (axis ? qx : qy) >> (d - other);
      for (uint32_t prefix : out)
        for (uint32_t bit = 0; bit < 2; ++bit) {
          const uint32_t c = (prefix << 1) | bit;
          if (!occ_[axis ? interval(other, fixed, c) : interval(bits, c, fixed)]) tmp_.push_back(c);
        }
      out.swap(tmp_);
      tmp_.clear();
    }
  }
  // Whether the shapes with at most d bits on either axis (fixed by the sub-square) are empty.
  bool square_free(uint32_t qx, uint32_t qy, int d) const {
    for (int a = std::max(0, L_ - d); a <= std::min(d, L_); ++a)
      if (occ_[interval(a, qx >> (d - a), qy >> (d - (L_ - a)))]) return false;
    return true;
  }

  // Places the next point in sub-square q0 or q1 (d bits per axis): of `candidates_`
  // candidates in their valid strata, the farthest from every earlier point.
  void place(int d, Square q0, std::optional<Square> q1 = std::nullopt) {
    const Square options[2] = {q0, q1.value_or(q0)};
    const int n_options = q1 ? 2 : 1;
    struct Option {
      Square q;
      std::vector<uint32_t> xs, ys;
    };
    Option opt[2];
    int live = 0;
    for (int o = 0; o < n_options; ++o) {
      Option& p = opt[live];
      p.q = options[o];
      if (!square_free(p.q.first, p.q.second, d)) continue;
      valid_strata(0, p.q.first, p.q.second, d, p.xs);
      valid_strata(1, p.q.first, p.q.second, d, p.ys);
      if (!p.xs.empty() && !p.ys.empty()) ++live;
    }
    if (!live) throw std::logic_error("pmj02bn: no valid stratum left for point " + std::to_string(size()));
    const uint32_t low = L_ >= 32 ? 0u : ~0u >> L_;
    double best = -1.0;
    uint32_t bx = 0, by = 0;
    for (int c = 0; c < candidates_; ++c) {
      const Option& p = opt[live == 1 ? 0 : rng_.below(uint64_t(live))];
      const uint32_t sx = p.xs[rng_.below(p.xs.size())], sy = p.ys[rng_.below(p.ys.size())];
      const uint64_t r = rng_.next_u64();
      const uint32_t X = (sx << (32 - L_)) | (uint32_t(r) & low), Y = (sy << (32 - L_)) | (uint32_t(r >> 32) & low);
      if (candidates_ == 1) {
        bx = X, by = Y;
        break;
      }
      const double dist = nearest(unit_from_u32(X), unit_from_u32(Y), best);
      if (dist > best) best = dist, bx = X, by = Y;
    }
    add(bx, by);
  }

  // The grid of 2^d x 2^d cells the nearest-point search walks: at most one point per cell,
  // since every prefix of up to 4^d points is a (0,2d,2)-net (or a prefix of one).
  void set_grid(int d) {
    g_ = 1 << d;
    h_ = 1.0 / g_;
    grid_.assign(std::size_t(g_) * g_, -1);
    for (int64_t i = 0; i < size(); ++i) grid_[cell(xy_[2 * i], xy_[2 * i + 1])] = int32_t(i);
  }
  std::size_t cell(uint32_t X, uint32_t Y) const {
    const int d = std::countr_zero(unsigned(g_));
    return std::size_t(fixed_top_bits(Y, d)) * g_ + fixed_top_bits(X, d);
  }

  // Toroidal distance from (x, y) to the nearest point; stops early with some distance at most
  // `stop` once one is found that close (the caller only keeps candidates beyond it).
  double nearest(double x, double y, double stop) const {
    double best2 = std::numeric_limits<double>::infinity();
    const double stop2 = stop >= 0 ? stop * stop : -1.0;
    const int cx = std::min(int(x * g_), g_ - 1), cy = std::min(int(y * g_), g_ - 1);
    auto visit = [&](int i, int j) {
      const int32_t p = grid_[std::size_t((j + g_) % g_) * g_ + std::size_t((i + g_) % g_)];
      if (p < 0) return false;
      const uint32_t* q = xy_.data() + 2 * std::size_t(p);
      double dx = std::abs(unit_from_u32(q[0]) - x), dy = std::abs(unit_from_u32(q[1]) - y);
      dx = std::min(dx, 1.0 - dx), dy = std::min(dy, 1.0 - dy);
      best2 = std::min(best2, dx * dx + dy * dy);
      return best2 <= stop2;
    };
    for (int r = 0; 2 * r - 1 < g_; ++r) {
      // Ring r: two rows, then two columns without their corners.
      for (int i = -r; i <= r; ++i)
        if (visit(cx + i, cy - r) || (r && visit(cx + i, cy + r))) return std::sqrt(best2);
      for (int j = -r + 1; j <= r - 1; ++j)
        if (visit(cx - r, cy + j) || visit(cx + r, cy + j)) return std::sqrt(best2);
      if (best2 <= (r * h_) * (r * h_)) break;  // points past ring r are more than r cells away
    }
    return std::sqrt(best2);
  }

  void add(uint32_t X, uint32_t Y) {
    const double inf = std::numeric_limits<double>::infinity();
    const double near = size() ? nearest(unit_from_u32(X), unit_from_u32(Y), -1.0) : inf;
    min_ = std::min(min_, near);
    radius_.push_back(min_);
    grid_[cell(X, Y)] = int32_t(size());
    xy_.push_back(X);
    xy_.push_back(Y);
    if (L_ >= 0) mark(X, Y);
  }

  int64_t count_;
  int candidates_;
  Rng rng_;
  std::vector<uint32_t> xy_;
  std::vector<double> radius_;
  double min_ = std::numeric_limits<double>::infinity();
  int L_ = -1;
  std::vector<uint8_t> occ_;
  mutable std::vector<uint32_t> tmp_;
  int g_ = 1;
  double h_ = 1.0;
  std::vector<int32_t> grid_;
};

void check(int64_t count, int candidates) {
  if (count < 1 || count > kPmj02bnMaxCount)
    throw UsageError("pmj02bn: count must be in 1.." + std::to_string(kPmj02bnMaxCount) + ", got " +
                     std::to_string(count));
  if (candidates < 1) throw UsageError("pmj02bn: candidates must be >= 1, got " + std::to_string(candidates));
}

}  // namespace

std::vector<uint32_t> pmj02bn_fixed(int64_t count, uint64_t seed, int candidates) {
  check(count, candidates);
  Builder b(count, seed, candidates);
  b.run();
  return b.take_xy();
}

PointSet pmj02bn(int64_t count, uint64_t seed, int candidates) {
  check(count, candidates);
  Builder b(count, seed, candidates);
  b.run();
  PointSet ps;
  ps.dim = 2;
  ps.periodic = true;
  const std::vector<uint32_t> xy = b.take_xy();
  ps.coords.reserve(xy.size());
  for (uint32_t v : xy) ps.coords.push_back(unit_from_u32(v));
  ps.radius = b.take_radius();
  return ps;
}

PointSet generate_pmj02bn(const GeneratorParams& p) {
  const int m = p.attempts ? int(std::min<int64_t>(*p.attempts, 1 << 20)) : kPmj02bnDefaultCandidates;
  return pmj02bn(*p.count, p.seed, m);
}

}  // namespace pdrt
