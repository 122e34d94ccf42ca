#include "sampling/generators/stratified_best_candidate_1d.h"

#include "sampling/core/errors.h"
#include "sampling/core/rng.h"
#include "sampling/generators/generator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace pdrt {

namespace {

// Distance from x to the nearest point of `s` (on the circle when periodic); +inf when empty.
double nearest(const std::set<double>& s, double x, bool periodic) {
  if (s.empty()) return std::numeric_limits<double>::infinity();
  auto hi = s.lower_bound(x);
  double d = std::numeric_limits<double>::infinity();
  if (hi != s.end())
    d = *hi - x;
  else if (periodic)
    d = *s.begin() + 1.0 - x;
  if (hi != s.begin())
    d = std::min(d, x - *std::prev(hi));
  else if (periodic)
    d = std::min(d, x + 1.0 - *s.rbegin());
  return d;
}

}  // namespace

PointSet stratified_best_candidate_1d(const StratifiedBestCandidate1D& p) {
  if (p.count < 1) throw UsageError("stratified-bc: count must be >= 1, got " + std::to_string(p.count));
  if (p.candidates < 1) throw UsageError("stratified-bc: candidates must be >= 1, got " + std::to_string(p.candidates));
  PointSet ps;
  ps.dim = 1;
  ps.periodic = p.periodic;
  ps.coords.reserve(std::size_t(p.count));
  ps.radius.reserve(std::size_t(p.count));
  Rng rng(p.seed, 0x737462635f3164ull);  // "stbc_1d"
  std::set<double> placed;
  double min_gap = std::numeric_limits<double>::infinity();
  for (int64_t j = 0; j < p.count; ++j) {
    // The stratum: all of [0, 1) for point 0, else the empty half of the parent's cell.
    double lo = 0.0, width = 1.0;
    if (j > 0) {
      const int k = 63 - __builtin_clzll(uint64_t(j));
      width = std::ldexp(1.0, -(k + 1));
      const double parent = ps.coords[std::size_t(j - (int64_t(1) << k))];
      const int64_t cell = int64_t(std::floor(parent / width)) ^ 1;
      lo = double(cell) * width;
    }
    double best = lo, best_d = -1.0;
    for (int c = 0; c < p.candidates; ++c) {
      // On the 32-bit fixed-point grid tables store, so the recorded gaps are the stored ones.
      const double x = std::ldexp(std::floor(std::ldexp(lo + width * rng.uniform(), 32)), -32);
      const double d = nearest(placed, x, p.periodic);
      if (d > best_d) best = x, best_d = d;
    }
    if (!placed.empty()) min_gap = std::min(min_gap, best_d);
    placed.insert(best);
    ps.coords.push_back(best);
    ps.radius.push_back(min_gap);
  }
  return ps;
}

PointSet generate_stratified_bc(const GeneratorParams& p) {
  StratifiedBestCandidate1D s;
  s.count = *p.count;
  s.seed = p.seed;
  s.periodic = p.periodic;
  if (p.attempts) s.candidates = int(std::min<int64_t>(*p.attempts, 1 << 20));
  return stratified_best_candidate_1d(s);
}

}  // namespace pdrt
