#include "sampling/generators/owen_poisson_2d.h"

#include "sampling/core/bit_reverse.h"
#include "sampling/core/errors.h"
#include "sampling/core/rng.h"
#include "sampling/generators/generator.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <queue>
#include <string>
#include <vector>

namespace pdrt {

namespace {

// A pair adds to the energy only below this rho (scores are capped there), so every
// neighbour search stays inside the 3x3 block of its level's dyadic grid of side
// 2^-floor(L/2) (needs cap <= sqrt(2 / sqrt 3) 2^(L/2 - floor(L/2)), 0.9306 for even L).
constexpr double kCap = 0.93;
constexpr int kMaxLevel = 16;

uint32_t sobol_second(uint32_t j) {  // x+1 polynomial: v_k = v_{k-1} ^ (v_{k-1} >> 1)
  uint32_t v = 1u << 31, y = 0;
  for (; j; j >>= 1, v ^= v >> 1)
    if (j & 1) y ^= v;
  return y;
}

// Top `bits` bits of v (0 for bits == 0).
uint32_t top(uint32_t v, int bits) { return bits ? v >> (32 - bits) : 0; }

int level_of(uint32_t j) { return std::bit_width(j); }  // j < 2^L, j >= 2^(L-1)

// Squared toroidal distance in units of 2^-32, exact: unsigned differences wrap around the
// torus. Integers keep the output the same whether or not the compiler fuses multiply-adds.
uint64_t dist2(uint32_t ax, uint32_t ay, uint32_t bx, uint32_t by) {
  const int64_t dx = int32_t(ax - bx), dy = int32_t(ay - by);
  return uint64_t(dx * dx) + uint64_t(dy * dy);
}

// Distinct cells c-r..c+r on a periodic axis of n cells (all of them when the block wraps).
int axis_block(uint32_t c, int r, uint32_t n, uint32_t* out) {
  if (uint32_t(2 * r + 1) >= n) {
    for (uint32_t i = 0; i < n; ++i) out[i] = i;
    return int(n);
  }
  for (int d = -r; d <= r; ++d) out[d + r] = (c + n + uint32_t(d)) & (n - 1);
  return 2 * r + 1;
}

// The 2^L-prefix on a dyadic grid of 2^g x 2^g cells, g = floor(L/2): a (0,L,2)-net puts
// exactly 2^(L-2g) (1 or 2) points in each cell, and a scramble keeps it so.
struct LevelGrid {
  int g = 0;
  int per = 1;                  // points per cell
  double scale = 0.0;           // rho per unit of distance at 2^-32: sqrt(sqrt3 2^L / 2) 2^-32
  double scale2 = 0.0;          // squared distance -> term table position
  double weight = 1.0;          // of this level's pairs in the energy
  double reach = 0.0;           // distance (2^-32 units) at which a pair's rho reaches the cap
  std::vector<uint32_t> cells;  // cell (a, b) holds cells[(a 2^g + b) per + s]

  uint32_t side() const { return 1u << g; }
};

class Optimiser {
 public:
  Optimiser(int m, int depth, uint64_t seed) : m_(m), n_(1u << m), depth_(depth) {
    tree_ = std::max(depth, m);
    for (int c = 0; c < 2; ++c) {
      orig_[c].resize(n_);
      pos_[c].resize(n_);
      perm_[c].resize(n_);
      flip_[c].assign((std::size_t(1) << tree_) - 1, 0);
    }
    for (uint32_t j = 0; j < n_; ++j) orig_[0][j] = reverse_bits32(j), orig_[1][j] = sobol_second(j);
    // Random Owen scramble: one hashed bit per node (depth k, prefix p); below the explicit
    // tree each point has its own nodes, folded into one mask.
    const uint64_t key = hash_combine(seed, 0x6f77656e5f7064ull);  // "owen_pd"
    auto node_bit = [&](int c, int k, uint32_t p) {
      return uint32_t(mix64(hash_combine(key, (uint64_t(c) << 40) ^ (uint64_t(k) << 32) ^ p)) >> 63);
    };
    for (int c = 0; c < 2; ++c) {
      for (int k = 0; k < tree_; ++k)
        for (uint32_t p = 0; p < (1u << k); ++p) flip_[c][(1u << k) - 1 + p] = uint8_t(node_bit(c, k, p));
      for (uint32_t j = 0; j < n_; ++j) {
        const uint32_t o = orig_[c][j];
        uint32_t s = o;
        for (int k = 0; k < 32; ++k) {
          const uint32_t b = k < tree_ ? flip_[c][(1u << k) - 1 + top(o, k)] : node_bit(c, k, top(o, k));
          s ^= b << (31 - k);
        }
        pos_[c][j] = s;
        perm_[c][top(o, m)] = j;
      }
    }
    // Inverse scramble of the prefixes the level grids use (depth <= m / 2), kept by toggle().
    for (int c = 0; c < 2; ++c) {
      inv_[c].assign((std::size_t(2) << (m / 2)) - 1, 0);
      for (int g = 0; g <= m / 2; ++g)
        for (uint32_t a = 0; a < (1u << g); ++a) inv_[c][(1u << g) - 1 + a] = unscramble(c, a, g);
    }
    levels_.resize(std::size_t(m) + 1);
    for (int L = 1; L <= m; ++L) {
      LevelGrid& lv = levels_[std::size_t(L)];
      lv.g = L / 2;
      lv.per = 1 << (L - 2 * lv.g);
      lv.scale = std::sqrt(std::sqrt(3.0) * std::ldexp(1.0, L) / 2.0) * 0x1.0p-32;
      lv.cells.assign(std::size_t(1) << L, 0);
      std::vector<int> fill(std::size_t(1) << (2 * lv.g), 0);
      for (uint32_t j = 0; j < (1u << L); ++j) {  // bucketed by original prefixes
        const uint32_t cell = (top(orig_[0][j], lv.g) << lv.g) | top(orig_[1][j], lv.g);
        lv.cells[cell * uint32_t(lv.per) + uint32_t(fill[cell]++)] = j;
      }
    }
  }

  // Annealing over the flips of nodes at depths 1..depth-1 (depth 0 is a half-period shift).
  void anneal(int sweeps, double beta, double t0, double level_weight, Rng& rng) {
    const double at_cap = std::exp(-beta * kCap);
    table_.resize(kTable);
    for (int i = 0; i < kTable; ++i)
      table_[std::size_t(i)] = std::exp(-beta * kCap * std::sqrt((double(i) + 0.5) / kTable)) - at_cap;
    for (int L = 1; L <= m_; ++L) {
      LevelGrid& lv = levels_[std::size_t(L)];
      lv.scale2 = lv.scale * lv.scale / (kCap * kCap) * kTable;
      lv.weight = std::exp2(level_weight * double(m_ - L));
      lv.reach = kCap / lv.scale;
    }
    stamp_.assign(n_, 0);
    std::vector<std::array<uint32_t, 2>> nodes;  // (coordinate, depth << 16 | prefix) with points
    for (int c = 0; c < 2; ++c)
      for (int k = 1; k < depth_; ++k)
        for (uint32_t p = 0; p < (1u << k); ++p)
          if (k <= m_ || (p & ((1u << (k - m_)) - 1)) == 0) nodes.push_back({uint32_t(c), uint32_t(k) << 16 | p});
    if (nodes.empty() || sweeps == 0 || m_ == 0) return;
    const int64_t steps = int64_t(sweeps) * int64_t(nodes.size());
    const double t1 = t0 * 1e-3, cool = t0 > 0 ? std::pow(t1 / t0, 1.0 / double(steps)) : 1.0;
    double t = t0;
    double energy = total();
    for (int64_t s = 0; s < steps; ++s, t *= cool) {
      if ((s & 0xffff) == 0xffff) energy = total();  // no drift from the running sums
      const auto [c, kp] = nodes[rng.below(nodes.size())];
      const double after = energy + propose(int(c), int(kp >> 16), kp & 0xffff);
      // Change of the soft-min -ln(E)/beta; Metropolis on it.
      const double gain = -(std::log(std::max(after, 1e-300)) - std::log(energy)) / beta;
      if (gain >= 0 || (t > 0 && rng.uniform() < std::exp(gain / t)))
        energy = after;
      else
        toggle(int(c), int(kp >> 16), kp & 0xffff);
    }
  }

  const std::vector<uint32_t>& pos(int c) const { return pos_[c]; }

 private:
  // Original prefix of depth g that the scramble maps to scrambled prefix a (walks the tree).
  uint32_t unscramble(int c, uint32_t a, int g) const {
    uint32_t o = 0;
    for (int i = 0; i < g; ++i) o = (o << 1) | (((a >> (g - 1 - i)) & 1) ^ flip_[c][(1u << i) - 1 + o]);
    return o;
  }

  // Visits the points of the 2^L-prefix in the 3x3 cells around (x, y) at level L's grid.
  template <class F>
  void around(int L, uint32_t x, uint32_t y, F&& f) const {
    const LevelGrid& lv = levels_[std::size_t(L)];
    uint32_t xs[3], ys[3];
    const int nx = axis_block(top(x, lv.g), 1, lv.side(), xs), ny = axis_block(top(y, lv.g), 1, lv.side(), ys);
    const uint32_t* ix = &inv_[0][(1u << lv.g) - 1];
    const uint32_t* iy = &inv_[1][(1u << lv.g) - 1];
    for (int i = 0; i < nx; ++i) xs[i] = ix[xs[i]];
    for (int i = 0; i < ny; ++i) ys[i] = iy[ys[i]];
    for (int i = 0; i < nx; ++i)
      for (int k = 0; k < ny; ++k) {
        const uint32_t* cell = &lv.cells[((xs[i] << lv.g) | ys[k]) * uint32_t(lv.per)];
        for (int s = 0; s < lv.per; ++s) f(cell[s]);
      }
  }

  // A pair's term at level L: exp(-beta rho) - exp(-beta cap), 0 beyond the cap. Summed over
  // a point's neighbours it is exp(-beta s) of a soft nearest-neighbour score s.
  // Tabulated on rho^2 in fine steps: no sqrt or exp per pair, and no multiply-add whose
  // fusing could change a decision.
  double term(int L, uint64_t d2) const {
    const LevelGrid& lv = levels_[std::size_t(L)];
    const double x = lv.scale2 * double(d2);
    return x < double(kTable) ? lv.weight * table_[std::size_t(x)] : 0.0;
  }

  // Each point i >= 1 against the other points of its level's prefix 2^L (L = level of i):
  // a pair inside one level counts twice, a pair across levels once (for the later point).
  double total() const {
    double e = 0;
    for (uint32_t i = 1; i < n_; ++i) {
      const int L = level_of(i);
      around(L, pos_[0][i], pos_[1][i], [&](uint32_t j) {
        if (j != i) e += term(L, dist2(pos_[0][i], pos_[1][i], pos_[0][j], pos_[1][j]));
      });
    }
    return e;
  }

  // Points under node (c, k, p): a run of the points sorted by that coordinate.
  std::pair<uint32_t, uint32_t> run(int k, uint32_t p) const {
    if (k <= m_) return {p << (m_ - k), (p + 1) << (m_ - k)};
    return {p >> (k - m_), (p >> (k - m_)) + 1};
  }

  void toggle(int c, int k, uint32_t p) {
    // Below the node the scrambled prefixes of its two halves trade places.
    uint32_t q = 0;  // scrambled image of p
    for (int i = 0; i < k && k < m_ / 2; ++i)
      q = (q << 1) | (((p >> (k - 1 - i)) & 1) ^ flip_[c][(1u << i) - 1 + (p >> (k - i))]);
    for (int g = k + 1; g <= m_ / 2; ++g) {
      uint32_t* row = &inv_[c][(1u << g) - 1 + (q << (g - k))];
      const uint32_t half = 1u << (g - k - 1);
      for (uint32_t i = 0; i < half; ++i) std::swap(row[i], row[i + half]);
    }
    flip_[c][(1u << k) - 1 + p] ^= 1;
    const auto [b, e] = run(k, p);
    for (uint32_t t = b; t < e; ++t) pos_[c][perm_[c][t]] ^= 1u << (31 - k);
  }

  // Change of the terms of the pairs (m, j) under the flip: it swaps the two halves of the
  // node's interval, so a pair changes unless both points are in the same half. A pair with
  // j in the other half is counted from the point that starts in the lower half. Levels whose
  // grid cell the flip keeps (k >= g) get old and new terms in one pass (0), the others the
  // old terms before the flip (pass 1) and the new ones after it (pass 2).
  double pairs(uint32_t m, int c, int k, int pass) const {
    const int lm = level_of(m);
    const uint32_t bit = 1u << (31 - k);
    const uint32_t x = pos_[0][m], y = pos_[1][m];
    const uint32_t nx = c == 0 ? x ^ bit : x, ny = c == 1 ? y ^ bit : y;  // m after the flip
    const bool lower = ((pos_[c][m] & bit) != 0) == (pass == 2);          // started in the lower half
    // Distance (along c) to the nearest of the node's edges and midline: a level whose reach
    // is shorter sees only points of m's own half, which move with it.
    const uint32_t off = pos_[c][m] & ((bit << 1) - 1);
    const uint32_t edge = std::min(std::min(off, (bit << 1) - off), off > bit ? off - bit : bit - off);
    double d = 0;
    for (int L = std::max(1, lm); L <= m_; ++L) {
      const LevelGrid& lv = levels_[std::size_t(L)];
      if (double(edge) > lv.reach) break;  // reach shrinks with L
      const bool same = k >= lv.g;
      if (same != (pass == 0)) continue;
      around(L, x, y, [&](uint32_t j) {
        const int lj = level_of(j);
        if (j == m || (L == lm ? lj > lm : lj != L)) return;
        uint32_t jx = pos_[0][j], jy = pos_[1][j];
        const bool moved = stamp_[j] == epoch_;
        if (moved && (!lower || ((pos_[c][j] ^ pos_[c][m]) & bit) == 0)) return;
        const double w = lj == lm ? 2.0 : 1.0;
        const double now = term(L, dist2(x, y, jx, jy));
        if (!same) {
          d += pass == 1 ? -w * now : w * now;
          return;
        }
        if (moved) (c == 0 ? jx : jy) ^= bit;
        d += w * (term(L, dist2(nx, ny, jx, jy)) - now);
      });
    }
    return d;
  }

  // Applies the flip and returns the change of the energy.
  double propose(int c, int k, uint32_t p) {
    ++epoch_;
    const auto [b, e] = run(k, p);
    for (uint32_t t = b; t < e; ++t) stamp_[perm_[c][t]] = epoch_;
    double delta = 0;
    for (uint32_t t = b; t < e; ++t) delta += pairs(perm_[c][t], c, k, 0) + pairs(perm_[c][t], c, k, 1);
    toggle(c, k, p);
    for (uint32_t t = b; t < e; ++t) delta += pairs(perm_[c][t], c, k, 2);
    return delta;
  }

  int m_;
  uint32_t n_;
  int depth_, tree_;
  static constexpr int kTable = 1 << 16;  // bins of rho^2 in [0, cap^2)
  std::vector<double> table_;
  std::array<std::vector<uint32_t>, 2> orig_, pos_, perm_;
  std::array<std::vector<uint8_t>, 2> flip_;  // node (k, p) at (1 << k) - 1 + p
  std::array<std::vector<uint32_t>, 2> inv_;  // scrambled prefix (g, a) at (1 << g) - 1 + a -> original
  std::vector<LevelGrid> levels_;
  std::vector<uint32_t> stamp_;
  uint32_t epoch_ = 0;
};

// Farthest-point order inside each level [2^(L-1), 2^L): the next point is the one farthest
// from every earlier point. Returns the order and each point's distance (2^-32 units,
// squared) to its nearest earlier point.
void farthest_first(const std::vector<uint32_t>& px, const std::vector<uint32_t>& py, int m,
                    std::vector<uint32_t>& order, std::vector<uint64_t>& nearest2) {
  const uint32_t n = 1u << m;
  order.assign(1, 0);
  nearest2.assign(1, UINT64_MAX);
  // Scrambled-space grid of each prefix: 2^g x 2^g cells of 2^(L-2g) points each.
  auto grid = [&](int L, std::vector<uint32_t>& cells) {
    const int g = L / 2, per = 1 << (L - 2 * g);
    cells.assign(std::size_t(1) << L, 0);
    std::vector<int> fill(std::size_t(1) << (2 * g), 0);
    for (uint32_t j = 0; j < (1u << L); ++j) {
      const uint32_t c = (top(px[j], g) << g) | top(py[j], g);
      cells[c * uint32_t(per) + uint32_t(fill[c]++)] = j;
    }
  };
  std::vector<uint32_t> prev, cur;
  std::vector<uint64_t> value(n, 0);
  std::vector<uint8_t> done(n, 0);
  std::vector<uint32_t> xs(1u << 10), ys(1u << 10);
  grid(0, prev);
  for (int L = 1; L <= m; ++L) {
    grid(L, cur);
    const uint32_t lo = 1u << (L - 1), hi = 1u << L;
    const int gp = (L - 1) / 2, pp = 1 << (L - 1 - 2 * gp), g = L / 2, per = 1 << (L - 2 * g);
    // Nearest point of the 2^(L-1)-prefix: every cell of its grid is occupied, so it lies
    // within sqrt2 cells, inside the 5x5 block.
    for (uint32_t j = lo; j < hi; ++j) {
      const int nx = axis_block(top(px[j], gp), 2, 1u << gp, xs.data()),
                ny = axis_block(top(py[j], gp), 2, 1u << gp, ys.data());
      uint64_t best = UINT64_MAX;
      for (int a = 0; a < nx; ++a)
        for (int b = 0; b < ny; ++b)
          for (int s = 0; s < pp; ++s) {
            const uint32_t i = prev[((xs[a] << gp) | ys[b]) * uint32_t(pp) + uint32_t(s)];
            best = std::min(best, dist2(px[j], py[j], px[i], py[i]));
          }
      value[j] = best;
    }
    // Lazy max-heap: larger value first, then the smaller index (deterministic ties).
    using Entry = std::pair<uint64_t, uint32_t>;
    auto less = [](const Entry& a, const Entry& b) {
      return a.first < b.first || (a.first == b.first && a.second > b.second);
    };
    std::priority_queue<Entry, std::vector<Entry>, decltype(less)> heap(less);
    for (uint32_t j = lo; j < hi; ++j) heap.push({value[j], j});
    while (!heap.empty()) {
      const auto [v, j] = heap.top();
      heap.pop();
      if (done[j] || v != value[j]) continue;
      done[j] = 1;
      order.push_back(j);
      nearest2.push_back(v);
      // Only candidates closer than v to j can get nearer to the placed set.
      const int r = std::min(int(std::sqrt(double(v)) / std::ldexp(1.0, 32 - g)) + 1, 256);
      const int nx = axis_block(top(px[j], g), r, 1u << g, xs.data()),
                ny = axis_block(top(py[j], g), r, 1u << g, ys.data());
      for (int a = 0; a < nx; ++a)
        for (int b = 0; b < ny; ++b)
          for (int s = 0; s < per; ++s) {
            const uint32_t i = cur[((xs[a] << g) | ys[b]) * uint32_t(per) + uint32_t(s)];
            if (i < lo || done[i]) continue;
            const uint64_t d = dist2(px[j], py[j], px[i], py[i]);
            if (d < value[i]) value[i] = d, heap.push({d, i});
          }
    }
    std::swap(prev, cur);
  }
}

}  // namespace

PointSet owen_poisson_2d(const OwenPoisson2D& p) {
  if (p.count < 1 || p.count > kOwenPoissonMaxCount)
    throw UsageError("owen-pd: count must be in 1.." + std::to_string(kOwenPoissonMaxCount) + ", got " +
                     std::to_string(p.count));
  if (p.depth < 1 || p.depth > kMaxLevel)
    throw UsageError("owen-pd: depth must be in 1..16, got " + std::to_string(p.depth));
  if (p.sweeps < 0) throw UsageError("owen-pd: sweeps must be >= 0, got " + std::to_string(p.sweeps));
  if (p.polish_sweeps < 0)
    throw UsageError("owen-pd: polish_sweeps must be >= 0, got " + std::to_string(p.polish_sweeps));
  if (!(p.beta > 0 && p.beta <= 1000))
    throw UsageError("owen-pd: beta must be in (0, 1000], got " + std::to_string(p.beta));
  if (!(p.polish_beta > 0 && p.polish_beta <= 1000))
    throw UsageError("owen-pd: polish_beta must be in (0, 1000], got " + std::to_string(p.polish_beta));
  if (!(p.temperature >= 0 && std::isfinite(p.temperature)))
    throw UsageError("owen-pd: temperature must be a finite number >= 0, got " + std::to_string(p.temperature));
  if (!(p.level_weight >= 0 && p.level_weight <= 4))  // 2^(4 x 16) still fits a double sum
    throw UsageError("owen-pd: level_weight must be in [0, 4], got " + std::to_string(p.level_weight));
  const int m = int(std::bit_width(uint64_t(p.count - 1)));  // 2^m >= count
  Optimiser opt(m, p.depth, p.seed);
  Rng rng(p.seed, 0x6f77656e2d7064ull);  // "owen-pd"
  opt.anneal(p.sweeps, p.beta, p.temperature, p.level_weight, rng);
  opt.anneal(p.polish_sweeps, p.polish_beta, p.temperature / 10, p.level_weight, rng);
  std::vector<uint32_t> order;
  std::vector<uint64_t> nearest2;
  farthest_first(opt.pos(0), opt.pos(1), m, order, nearest2);
  PointSet ps;
  ps.dim = 2;
  ps.periodic = true;
  ps.coords.reserve(std::size_t(p.count) * 2);
  ps.radius.reserve(std::size_t(p.count));
  uint64_t min2 = UINT64_MAX;
  for (int64_t i = 0; i < p.count; ++i) {
    const uint32_t j = order[std::size_t(i)];
    ps.coords.push_back(unit_from_u32(opt.pos(0)[j]));
    ps.coords.push_back(unit_from_u32(opt.pos(1)[j]));
    min2 = std::min(min2, nearest2[std::size_t(i)]);
    ps.radius.push_back(min2 == UINT64_MAX ? std::numeric_limits<double>::infinity()
                                           : std::sqrt(double(min2)) * 0x1.0p-32);
  }
  return ps;
}

PointSet generate_owen_pd(const GeneratorParams& p) {
  OwenPoisson2D o;
  o.count = *p.count;
  o.seed = p.seed;
  o.depth = std::max(o.depth, int(std::bit_width(uint64_t(o.count - 1))));  // every level optimised
  return owen_poisson_2d(o);
}

}  // namespace pdrt
