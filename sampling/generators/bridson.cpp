// `bridson`: Bridson 2007, "Fast Poisson Disk Sampling in Arbitrary Dimensions". An active
// list grows from a random seed point; each active point tries k candidates drawn uniformly
// from the spherical annulus [r, 2r) around it and retires when all k fail. O(N).
// In n-D candidates are drawn from the annulus directly (uniform direction, radius with
// density ~ rho^(n-1)), not by rejection from a 4^n box, which collapses in 4–5-D; 2-D has
// its own path (below), tuned for throughput.
#include "sampling/generators/generator.h"
#include "sampling/generators/detail/neighbor_grid.h"
#include "sampling/core/distance.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pdrt {
namespace {

// ---- 2-D fast path -------------------------------------------------------------------
//
// Background grid (Bridson step 0) of cell side s just under r/sqrt(2), so a cell holds at
// most one point, padded with ghost cells so queries never bounds-check; periodic ghosts
// hold wrapped copies. When also s >= r/1.5, a candidate in the left (right) half of its
// cell is > r from every cell two columns to the right (left), and likewise for rows, so a
// 4x4 block of cells holds all its neighbours.
//
// Each cell stores its point's position in units of 1/4096 cell, modulo 2^16, as two int16:
// wrapping int16 differences are exact within a block, so a block row is one 16-byte load
// and pmaddwd gives four squared distances. Truncating both ends to that lattice moves a
// distance by < sqrt(2) units, so comparing with r -/+ 1.5 units decides every candidate
// exactly except inside that band, which is redone in doubles from the point indices: the
// output is exactly that of an all-double test. Four candidates are tested together,
// without branches.
using V2d = double __attribute__((vector_size(16)));

class Grid2D {
 public:
  Grid2D(double r, bool periodic) : periodic_(periodic), r2_(r * r) {
    res_ = resolution(r);
    stride_ = res_ + 2 * kPad;
    scale_ = double(res_) * kUnit;
    last_ = res_ * kUnit - 1;
    const std::size_t cells = std::size_t(stride_) * std::size_t(stride_);
    id_.assign(cells, -1);
    // An empty cell holds a phantom 6 cells to its right: > 3.5 cells from any candidate
    // whose block includes it, and no int16 or pmaddwd overflow.
    pos_.resize(cells);
    for (int cy = -kPad; cy < res_ + kPad; ++cy)
      for (int cx = -kPad; cx < res_ + kPad; ++cx) pos_[index(cx, cy)] = pack((cx + 6) * kUnit, cy * kUnit + kUnit / 2);
    // Squared distances in units^2: a conflict below lo_, clear above hi_.
    const double ru = r * scale_;
    lo_ = int32_t(std::floor((ru - 1.5) * (ru - 1.5)));
    hi_ = int32_t(std::ceil((ru + 1.5) * (ru + 1.5)));
  }

  // The 4x4 block needs s >= r/1.5: true for r < 0.085, i.e. beyond ~100 points; a stride
  // below 2^15 keeps units and the int16 index product in int32.
  static bool applies(double r) {
    const int res = resolution(r);
    return res <= 1.5 / r * (1.0 - 1e-9) && res + 2 * kPad < 0x8000;
  }
  // Lattice units per unit of length.
  double scale() const { return scale_; }
  // A point's position in lattice units, as clear() takes it (biased to stay positive).
  V2d units(V2d x) const { return x * scale_ + double(kBias); }

  // For N (2 or 4) candidates given in lattice units (within 2r of the domain; unwrapped in
  // periodic mode): bit i of the result is set when candidate i is farther than r from
  // every stored point, bit i of `unsure` when the lattice cannot tell (use conflicts()).
  template <int N>
  [[gnu::always_inline]] unsigned clear(const V2d* u, unsigned& unsure) const;

  // Exact test over the 5x5 block: true when a stored point is closer than r to (x, y).
  bool conflicts(double x, double y, const double* pts) const {
    const int cx = unit(x) >> kBits, cy = unit(y) >> kBits;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int32_t i = id_[index(cx + dx, cy + dy)];
        if (i < 0) continue;
        const double ex = axis_delta(x, pts[2 * i], periodic_), ey = axis_delta(y, pts[2 * i + 1], periodic_);
        if (ex * ex + ey * ey < r2_) return true;
      }
    return false;
  }

  void insert(double x, double y, int32_t id) {
    const int32_t u = unit(x), v = unit(y);
    const int cx = u >> kBits, cy = v >> kBits;
    put(cx, cy, u, v, id);
    // Ghost copies across the wrap, out to the padding (unwrapped candidates reach it).
    if (!periodic_ || (cx >= kPad && cx < res_ - kPad && cy >= kPad && cy < res_ - kPad)) return;
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        const int gx = cx + ox * res_, gy = cy + oy * res_;
        if ((ox || oy) && gx >= -kPad && gx < res_ + kPad && gy >= -kPad && gy < res_ + kPad)
          put(gx, gy, u + ox * res_ * kUnit, v + oy * res_ * kUnit, id);
      }
  }

 private:
  // Candidates lie within 2r < 3 cells of the domain, their blocks within 5.
  static constexpr int kPad = 5, kBits = 12, kUnit = 1 << kBits;
  // 8 cells: keeps candidates' units positive, so truncation is the floor.
  static constexpr int kBias = 8 * kUnit;

  // Cells per axis: s a hair under r/sqrt(2) so rounding never puts two points in one
  // cell; 2s >= r, so the 5x5 block of the exact test covers the disk of radius r.
  static int resolution(double r) { return std::max(3, int(std::ceil(std::sqrt(2.0) / r * (1.0 + 1e-9)))); }
  static uint32_t pack(int32_t u, int32_t v) { return (uint32_t(u + kBias) & 0xffffu) | uint32_t(v + kBias) << 16; }
  // Unbiased units of x in [0, 1), truncated (clamped: x * scale_ may round up to the edge).
  int32_t unit(double x) const { return std::min(int32_t(x * scale_), last_); }
  std::size_t index(int cx, int cy) const { return std::size_t(cy + kPad) * stride_ + std::size_t(cx + kPad); }
  void put(int cx, int cy, int32_t u, int32_t v, int32_t id) {
    const std::size_t c = index(cx, cy);
    pos_[c] = pack(u, v);
    id_[c] = id;
  }

  bool periodic_;
  double r2_, scale_;
  int res_, stride_;
  int32_t last_, lo_, hi_;
  std::vector<uint32_t> pos_;  // (v << 16) | u, biased units mod 2^16, of the point or phantom
  std::vector<int32_t> id_;    // point index, or -1
};

#if defined(__SSE2__)
template <int N>
inline unsigned Grid2D::clear(const V2d* u, unsigned& unsure) const {
  static_assert(N == 2 || N == 4);
  __m128i uv[4];
  for (int i = 0; i < N; ++i) uv[i] = _mm_cvttpd_epi32(__m128d(u[i]));  // (u, v, 0, 0)
  // Block origins, all at once: two cells before the nearest cell edge, less the bias's
  // 8 cells; tx + ty * stride by pmaddwd.
  const __m128i half = _mm_set1_epi32(kUnit / 2);
  const __m128i t01 = _mm_srai_epi32(_mm_add_epi32(_mm_unpacklo_epi64(uv[0], uv[1]), half), kBits);
  const __m128i t23 = N == 4 ? _mm_srai_epi32(_mm_add_epi32(_mm_unpacklo_epi64(uv[2], uv[3]), half), kBits) : t01;
  alignas(16) int32_t org[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(org),
                  _mm_madd_epi16(_mm_packs_epi32(t01, t23), _mm_set1_epi32(int32_t(uint32_t(stride_) << 16 | 1))));
  const uint32_t* base = pos_.data() - std::ptrdiff_t(10 - kPad) * (stride_ + 1);
  __m128 m[4];
  for (int i = 0; i < N; ++i) {
    const uint32_t* p = base + org[i];
    const __m128i q = _mm_shuffle_epi32(_mm_shufflelo_epi16(uv[i], 0x08), 0);  // (u, v) mod 2^16, x4
    for (int j = 0; j < 4; ++j, p += stride_) {
      const __m128i e = _mm_sub_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), q);
      // Squares below 2^30 order like the floats with the same bits, so minps is an integer
      // min (the smallest are denormals, all far below lo_: denormals-are-zero is harmless).
      const __m128 d2 = _mm_castsi128_ps(_mm_madd_epi16(e, e));
      m[i] = j ? _mm_min_ps(m[i], d2) : d2;
    }
  }
  if constexpr (N == 2) m[2] = m[0], m[3] = m[1];
  // Transpose-and-min: lane i of `mins` is candidate i's smallest squared distance.
  const __m128 a = _mm_min_ps(_mm_unpacklo_ps(m[0], m[1]), _mm_unpackhi_ps(m[0], m[1]));
  const __m128 b = N == 4 ? _mm_min_ps(_mm_unpacklo_ps(m[2], m[3]), _mm_unpackhi_ps(m[2], m[3])) : a;
  const __m128i mins = _mm_castps_si128(_mm_min_ps(_mm_movelh_ps(a, b), _mm_movehl_ps(b, a)));
  const unsigned clear = unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(mins, _mm_set1_epi32(hi_)))));
  const unsigned near = unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmplt_epi32(mins, _mm_set1_epi32(lo_)))));
  unsure = ~(clear | near) & ((1u << N) - 1);
  return clear & ((1u << N) - 1);
}
#else
// The same lattice test in scalar code.
template <int N>
inline unsigned Grid2D::clear(const V2d* u, unsigned& unsure) const {
  unsigned clear = 0, near = 0;
  for (int i = 0; i < N; ++i) {
    const int32_t cu = int32_t(u[i][0]), cv = int32_t(u[i][1]);
    const int tx = (cu + kUnit / 2) >> kBits, ty = (cv + kUnit / 2) >> kBits;
    const uint32_t* p = pos_.data() + (std::ptrdiff_t(ty) - (10 - kPad)) * stride_ + (tx - (10 - kPad));
    int32_t best = INT32_MAX;
    for (int j = 0; j < 4; ++j, p += stride_)
      for (int c = 0; c < 4; ++c) {
        const int32_t ex = int16_t(uint16_t(p[c] - uint32_t(cu))), ey = int16_t(uint16_t((p[c] >> 16) - uint32_t(cv)));
        best = std::min(best, ex * ex + ey * ey);
      }
    clear |= unsigned(best > hi_) << i;
    near |= unsigned(best < lo_) << i;
  }
  unsure = ~(clear | near) & ((1u << N) - 1);
  return clear;
}
#endif

// Annulus offsets, uniform in [r, 2r). One 64-bit draw is two signed 32-bit coordinates
// (a, b) in units of 2r / 2^31, uniform in the bounding square of the disk of radius 2r;
// outside that disk it is rejected. Inside, 2^j (a, b) with the j that brings it into the
// annulus is uniform there too (the disk is the union of the annulus scaled by 2^-j, each
// holding 4^-j of the area), so a draw is kept with probability pi/4 instead of the ring's
// 3*pi/16. j comes from the exact integer a^2 + b^2 and is applied to the step size.
// Drawn in branch-free batches and consumed in order, so every candidate is an independent
// uniform draw. Its own engines (seeded from the run's) are pcg64_once_insecure: a 64-bit
// LCG step and an RXS-M-XS output, the cheapest pcg per 64 bits (no 128-bit multiply;
// each output once per 2^64-long period, far beyond a run's draws; "insecure" only means
// predictable); two alternate so their multiply chains overlap.
class AnnulusStream {
  using Engine = pcg64_once_insecure;

 public:
  explicit AnnulusStream(Rng& rng) : engine_{engine(rng), engine(rng)} {}

  // Draws i < 4 from the read position and the leading zeros of their a^2 + b^2 (64-bit);
  // take(n) moves past n.
  const uint64_t* peek() {
    if (end_ - pos_ < 4) refill();
    return &buf_[pos_];
  }
  const uint32_t* clzs() const { return &clz_[pos_]; }
  void take(int n) { pos_ += n; }

 private:
  static constexpr int kBatch = 256;
  [[gnu::noinline]] void refill() {  // rare; out of line the engine state stays in registers
    // Move the (< 4) leftovers to the front; moving four is branch-free.
    std::size_t n = std::size_t(end_ - pos_);  // size_t: no sign extension per store
    std::memmove(buf_, buf_ + pos_, 4 * sizeof(buf_[0]));
    std::memmove(clz_, clz_ + pos_, 4 * sizeof(clz_[0]));
    Engine e0 = engine_[0], e1 = engine_[1];
    auto draw = [&](Engine& e) {
      const uint64_t w = e();
      const int64_t a = int32_t(uint32_t(w)), b = int32_t(uint32_t(w >> 32));
      const uint64_t q = uint64_t(a * a) + uint64_t(b * b);  // up to 2^63: unsigned sum
      buf_[n] = w;
      // The caller maps the leading zeros of q to j (4^j q in [2^60, 2^62)); q | 1 keeps
      // them defined (q = 0 is rejected below).
      clz_[n] = uint32_t(__builtin_clzll(q | 1));
      n += q - 1 < (uint64_t(1) << 62) - 1;  // 0 < q < 2^62
    };
    while (n < 4)
      for (int i = 0; i < kBatch; i += 2) draw(e0), draw(e1);
    engine_[0] = e0;
    engine_[1] = e1;
    pos_ = 0;
    end_ = int(n);
  }

  static Engine engine(Rng& rng) {
    const uint64_t seed = rng.next_u64();  // two statements: a fixed order
    return Engine(seed, rng.next_u64());
  }

  Engine engine_[2];
  int pos_ = 0, end_ = 0;
  // Room for a batch after 3 leftovers, and for the 4-entry moves. clz_ is not a char
  // type, so its stores cannot alias the engine.
  uint64_t buf_[kBatch + 8] = {};
  uint32_t clz_[kBatch + 8] = {};
};

// The two signed 32-bit halves of w as doubles.
inline V2d halves(uint64_t w) {
#if defined(__SSE2__)
  return V2d(_mm_cvtepi32_pd(_mm_cvtsi64_si128(int64_t(w))));
#else
  return V2d{double(int32_t(uint32_t(w))), double(int32_t(uint32_t(w >> 32)))};
#endif
}

template <bool kPeriodic>
PointSet bridson_2d(const GeneratorParams& p, double r, std::size_t limit) {
  const int k = int(p.attempts.value_or(30));
  Grid2D grid(r, kPeriodic);
  Rng rng(p.seed, 0x62726964);
  PointSet ps;
  ps.dim = 2;
  std::vector<V2d> active;  // coordinates, not indices: no random access into ps
  ps.coords.reserve(2 * std::size_t(std::min<double>(double(limit), expected_count_for_radius(r, 2) * 1.3)));
  std::size_t n = 0;  // points so far (ps.size() divides)
  auto add = [&](V2d c) {
    grid.insert(c[0], c[1], int32_t(n++));
    active.push_back(c);
    ps.coords.push_back(c[0]);
    ps.coords.push_back(c[1]);
  };
  add(V2d{rng.uniform(), rng.uniform()});
  AnnulusStream ring(rng);
  // Offset of draw (a, b) whose a^2 + b^2 has z leading zeros (z >= 2 once accepted):
  // (a, b) * step[z] with step[z] = 2^j * 2r / 2^31, j = (z - 2) / 2 (an exact power-of-two
  // scaling); ustep in lattice units.
  V2d step[64], ustep[64];
  for (int z = 0; z < 64; ++z) {
    step[z] = V2d{1, 1} * std::ldexp(r, std::max(z - 2, 0) / 2 - 30);
    ustep[z] = step[z] * grid.scale();
  }
  while (!active.empty() && n < limit) {
    const std::size_t slot = rng.below(active.size());
    const V2d parent = active[slot], upar = grid.units(parent);
    // The k candidates in groups of four (the first group takes k mod 4, so the last is
    // full), tested together: independent loads, one branch. The first that passes wins,
    // as if they were tried one by one. The lattice test takes unwrapped candidates in
    // units; coordinates are formed only for the few it leaves.
    auto group = [&]<int N>(int g) {
      const uint64_t* w = ring.peek();
      const uint32_t* z = ring.clzs();
      V2d u[N];
      for (int i = 0; i < N; ++i) u[i] = upar + halves(w[i]) * ustep[z[i]];
      unsigned unsure;
      const unsigned valid = (1u << g) - 1, clear = grid.template clear<N>(u, unsure) & valid;
      for (unsigned open = clear | (unsure & valid); open; open &= open - 1) {
        const int i = std::countr_zero(open);
        V2d c = parent + halves(w[i]) * step[z[i]];
        if constexpr (kPeriodic) {
          c[0] = c[0] < 0.0 ? c[0] + 1.0 : c[0];
          c[1] = c[1] < 0.0 ? c[1] + 1.0 : c[1];
          c[0] = c[0] >= 1.0 ? c[0] - 1.0 : c[0];  // also catches -tiny + 1 rounding to 1
          c[1] = c[1] >= 1.0 ? c[1] - 1.0 : c[1];
        } else if (!(c[0] >= 0.0 && c[0] < 1.0 && c[1] >= 0.0 && c[1] < 1.0)) {
          continue;  // outside the domain: a failed attempt
        }
        if ((clear >> i & 1) || !grid.conflicts(c[0], c[1], ps.coords.data())) {
          ring.take(i + 1);
          add(c);
          return true;
        }
      }
      ring.take(g);
      return false;
    };
    const int first = (k - 1) % 4 + 1;
    bool found = first <= 2 ? group.template operator()<2>(first) : group.template operator()<4>(first);
    for (int t = first; t < k && !found; t += 4) found = group.template operator()<4>(4);
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
  PointSet ps = p.dim != 2 || !Grid2D::applies(r) ? bridson_nd(p, r, limit)
                : p.periodic                      ? bridson_2d<true>(p, r, limit)
                                                  : bridson_2d<false>(p, r, limit);
  ps.radius.assign(ps.size(), r);
  return ps;
}

}  // namespace pdrt
