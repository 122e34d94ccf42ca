#include "sampling/generators/stratified_poisson_2d.h"

#include "sampling/core/errors.h"
#include "sampling/core/fixed_point.h"
#include "sampling/core/rng.h"
#include "sampling/generators/generator.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace pdrt {
namespace {

constexpr double kFixed = 0x1.0p-32;

// Nearest-point queries on the torus: a uniform grid searched ring by ring.
class TorusGrid {
 public:
  explicit TorusGrid(int64_t n) : g_(std::max(1, int(std::sqrt(double(n) / 2.0)))), cells_(std::size_t(g_) * g_) {}

  void insert(double x, double y) {
    cells_[cell(x, y)].push_back({x, y});
    all_.push_back({x, y});
  }

  // Distance to the nearest point, or some distance below `stop` as soon as one is found
  // (the caller only wants candidates that beat `stop`); +inf when empty.
  double nearest(double x, double y, double stop) const {
    double best = std::numeric_limits<double>::infinity();
    const double stop2 = stop > 0 ? stop * stop : -1.0;
    auto visit = [&](const std::vector<std::array<double, 2>>& pts) {
      for (const auto& q : pts) {
        double dx = std::abs(q[0] - x), dy = std::abs(q[1] - y);
        dx = std::min(dx, 1.0 - dx), dy = std::min(dy, 1.0 - dy);
        best = std::min(best, dx * dx + dy * dy);
      }
      return best < stop2;
    };
    // Few points: a scan beats rings that must grow across an empty grid.
    if (all_.size() < 64) {
      visit(all_);
      return std::sqrt(best);
    }
    const int cx = std::min(int(x * g_), g_ - 1), cy = std::min(int(y * g_), g_ - 1);
    const double h = 1.0 / g_;
    for (int r = 0; 2 * r - 1 < g_; ++r) {
      // The cells at Chebyshev distance r: two rows, then two columns without their corners.
      for (int i = -r; i <= r; ++i) {
        if (visit(cells_[std::size_t(wrap(cy - r)) * g_ + wrap(cx + i)])) return std::sqrt(best);
        if (r && visit(cells_[std::size_t(wrap(cy + r)) * g_ + wrap(cx + i)])) return std::sqrt(best);
      }
      for (int j = -r + 1; j <= r - 1; ++j) {
        if (visit(cells_[std::size_t(wrap(cy + j)) * g_ + wrap(cx - r)])) return std::sqrt(best);
        if (visit(cells_[std::size_t(wrap(cy + j)) * g_ + wrap(cx + r)])) return std::sqrt(best);
      }
      if (best <= (r * h) * (r * h)) break;  // points beyond ring r are >= r cell widths away
    }
    return std::sqrt(best);
  }

 private:
  int wrap(int i) const { return ((i % g_) + g_) % g_; }
  std::size_t cell(double x, double y) const {
    return std::size_t(std::min(int(y * g_), g_ - 1)) * g_ + std::min(int(x * g_), g_ - 1);
  }
  int g_;
  std::vector<std::vector<std::array<double, 2>>> cells_;
  std::vector<std::array<double, 2>> all_;
};

// Occupancy of the elementary intervals of one level L: shape a (a bits of x, L - a of y).
struct Level {
  int L = -1, sx = 0, sy = 0;  // the reference (most square) shape (sx, sy), sx = ceil(L/2)
  std::vector<uint8_t> occ_;   // shape a's interval i at occ_[(a << L) + i]
  uint8_t& occ(int a, uint32_t i) { return occ_[(std::size_t(a) << L) + i]; }
  uint8_t occ(int a, uint32_t i) const { return occ_[(std::size_t(a) << L) + i]; }
  std::vector<uint32_t> open;  // free intervals of the reference shape

  static uint32_t index(uint32_t X, uint32_t Y, int a, int L) {
    return (fixed_top_bits(X, a) << (L - a)) | fixed_top_bits(Y, L - a);
  }

  void reset(int level, const std::vector<uint32_t>& fixed_xy) {
    L = level, sx = (L + 1) / 2, sy = L - sx;
    occ_.assign(std::size_t(L + 1) << L, 0);
    for (std::size_t k = 0; k < fixed_xy.size(); k += 2) mark(fixed_xy[k], fixed_xy[k + 1]);
    open.clear();
    for (uint32_t i = 0; i < (1u << L); ++i)
      if (!occ(sx, i)) open.push_back(i);
  }
  void mark(uint32_t X, uint32_t Y) {
    for (int a = 0; a <= L; ++a) occ(a, index(X, Y, a, L)) = 1;
  }
  void take(uint32_t X, uint32_t Y) {
    mark(X, Y);
    const uint32_t r = index(X, Y, sx, L);
    auto it = std::find(open.begin(), open.end(), r);
    if (it != open.end()) *it = open.back(), open.pop_back();
  }

  // Occupied intervals that (X, Y) would share, weighted 4^min(a, L - a): sharing one of
  // the most square shape costs more than sharing all the more elongated ones.
  int violations(uint32_t X, uint32_t Y) const {
    int v = 0;
    for (int a = 0; a <= L; ++a) v += occ(a, index(X, Y, a, L)) << (2 * std::min(a, L - a));
    return v;
  }

  // The candidate of reference interval `ref` keeping the shapes a in [d, L - d]: each bit
  // below the interval is the child whose interval of the next shape is still empty (forced
  // when the sibling holds a point; random when both are free). A dropped shape's bit is
  // random, or the empty child when `prefer_empty`. False when a kept shape has both
  // children taken.
  bool complete(uint32_t ref, int d, bool prefer_empty, Rng& rng, uint32_t& X, uint32_t& Y) const {
    uint32_t xb = ref >> sy, yb = ref & ((1u << sy) - 1u);  // sx and sy top bits
    const uint32_t yref = yb, xref = xb;
    uint64_t coins = rng.next_u64();     // one bit per free choice (at most 2 x 32)
    for (int a = sx + 1; a <= L; ++a) {  // shape (a, L - a): y's top L - a bits are known
      const uint32_t yt = yref >> (sy - (L - a));
      int pick = int(coins & 1);
      coins >>= 1;
      const bool kept = a <= L - d;
      if (kept || prefer_empty) {
        const bool t0 = occ(a, ((xb << 1) << (L - a)) | yt), t1 = occ(a, (((xb << 1) | 1) << (L - a)) | yt);
        if (t0 && t1 && kept) return false;
        if (t0 != t1) pick = t0 ? 1 : 0;
      }
      xb = (xb << 1) | uint32_t(pick);
    }
    for (int b = sy + 1; b <= L; ++b) {  // shape (L - b, b): x's top L - b bits are known
      const uint32_t xt = xref >> (sx - (L - b));
      int pick = int(coins & 1);
      coins >>= 1;
      const bool kept = L - b >= d;
      if (kept || prefer_empty) {
        const bool t0 = occ(L - b, (xt << b) | (yb << 1)), t1 = occ(L - b, (xt << b) | (yb << 1) | 1);
        if (t0 && t1 && kept) return false;
        if (t0 != t1) pick = t0 ? 1 : 0;
      }
      yb = (yb << 1) | uint32_t(pick);
    }
    const uint64_t low = rng.next_u64();
    const uint32_t mask = L >= 32 ? 0u : ~0u >> L;
    X = (L ? xb << (32 - L) : 0u) | (uint32_t(low) & mask);
    Y = (L ? yb << (32 - L) : 0u) | (uint32_t(low >> 32) & mask);
    return true;
  }
};

}  // namespace

PointSet stratified_poisson_2d(const StratifiedPoisson2D& p) {
  if (p.count < 1 || p.count > (int64_t(1) << 20))
    throw UsageError("stratified-pd: count must be in 1..1048576, got " + std::to_string(p.count));
  if (p.candidates < 1) throw UsageError("stratified-pd: candidates must be >= 1, got " + std::to_string(p.candidates));
  for (double f : {p.prefix_floor, p.whole_floor})
    if (!(f >= 0.0 && f <= 1.0))
      throw UsageError("stratified-pd: rho floors must be in [0, 1], got " + std::to_string(f));
  const int64_t N = p.count;
  Rng rng(p.seed, 0x73747264706432ull);  // "strdpd2"
  PointSet ps;
  TorusGrid grid(N);
  Level level;
  std::vector<uint32_t> fixed_xy;
  double min_dist = std::numeric_limits<double>::infinity();
  // The first prefix the floor judges is drawn again (up to kRestarts times) until its points
  // keep the floor inside the square strata: a greedy start that had to leave them would
  // leave the small prefixes, where strata matter most, unstratified.
  constexpr int kRestarts = 256;
  int restarts = 0;
  auto restart = [&] {
    ps = PointSet{};
    ps.dim = 2;
    ps.periodic = true;
    ps.coords.reserve(std::size_t(2 * N));
    ps.radius.reserve(std::size_t(N));
    grid = TorusGrid(N);
    level = Level{};
    fixed_xy.clear();
    fixed_xy.reserve(std::size_t(2 * N));
    min_dist = std::numeric_limits<double>::infinity();
  };
  restart();
  for (int64_t n = 0; n < N; ++n) {
    const int L = int(std::bit_width(uint64_t(n)));
    if (L != level.L) level.reset(L, fixed_xy);
    const int64_t m = n + 1;  // the prefix this point completes
    double need = 0.0;
    if (m >= 2) {
      // Points before the first judged prefix are part of it: they keep its distance.
      const int64_t k = std::min(N, std::max(m, p.first_prefix));
      const double rho = std::max(p.prefix_floor, p.whole_floor * std::sqrt(double(k) / double(N)));
      need = rho * max_packing_distance(k, 2) * (1.0 + 1e-12);
    }
    // The winner: of the candidates that keep the floor, the one sharing the fewest occupied
    // intervals, then the farthest; if none keeps it, the farthest.
    struct Best {
      double dist = -1.0;
      int viol = 0;
      bool meets = false;
      uint32_t X = 0, Y = 0;
    } best;
    auto consider = [&](uint32_t X, uint32_t Y) {
      const int v = level.violations(X, Y);
      if (best.meets && v > best.viol) return;
      // The search stops early below `stop`, so only distances that can win are exact.
      const double stop = best.meets && v == best.viol ? best.dist : std::max(need, best.meets ? 0.0 : best.dist);
      const double d = grid.nearest(X * kFixed, Y * kFixed, stop);
      if (d >= need) {
        if (!best.meets || v < best.viol || d > best.dist) best = {d, v, true, X, Y};
      } else if (!best.meets && d > best.dist) {
        best = {d, v, false, X, Y};
      }
    };
    // Stratified candidates from m random open intervals, dropping the most elongated shapes
    // only while the floor needs it. With shapes dropped, several completions of each
    // interval, the first keeping the dropped strata where it can. (Trying every open
    // interval before dropping shapes costs 6x the time for no measurable gain.)
    for (int d = 0; d <= level.L / 2 && !best.meets; ++d) {
      auto& open = level.open;
      int tried = 0;
      for (std::size_t k = 0; k < open.size() && tried < p.candidates; ++k) {
        std::swap(open[k], open[k + rng.below(open.size() - k)]);  // a random subset, in place
        // The last level keeps only the squares: small prefixes search them finely.
        const int completions = d == 0 ? 1 : d < level.L / 2 || level.L > 6 ? 4 : 32;
        for (int c = 0; c < completions; ++c) {
          uint32_t X, Y;
          if (!level.complete(open[k], d, c == 0, rng, X, Y)) continue;
          ++tried;
          consider(X, Y);
        }
      }
    }
    if (!best.meets && n < p.first_prefix && restarts < kRestarts) {
      ++restarts;
      restart();
      n = -1;
      continue;
    }
    // Plain best candidate: the floor is worth more than the strata.
    for (int round = 0; !best.meets && round < 256; ++round)
      for (int c = 0; c < 64; ++c) {
        const uint64_t r = rng.next_u64();
        consider(uint32_t(r), uint32_t(r >> 32));
      }
    const uint32_t bx = best.X, by = best.Y;
    fixed_xy.push_back(bx);
    fixed_xy.push_back(by);
    level.take(bx, by);
    const double placed = grid.nearest(bx * kFixed, by * kFixed, -1.0);  // exact, also for a fallback
    grid.insert(bx * kFixed, by * kFixed);
    ps.coords.push_back(bx * kFixed);
    ps.coords.push_back(by * kFixed);
    if (n > 0) min_dist = std::min(min_dist, placed);
    ps.radius.push_back(min_dist);
  }
  return ps;
}

}  // namespace pdrt

namespace pdrt {

PointSet generate_stratified_pd(const GeneratorParams& p) {
  StratifiedPoisson2D s;
  s.count = *p.count;
  s.seed = p.seed;
  if (p.attempts) s.candidates = int(std::min<int64_t>(*p.attempts, 1 << 20));
  return stratified_poisson_2d(s);
}

}  // namespace pdrt
