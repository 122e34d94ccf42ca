// Elementary-interval checks by counting: one occupancy bitmap per interval shape.
#include "sampling/measures/elementary_intervals.h"

#include "sampling/core/fixed_point.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace pdrt {
namespace {

// Interval index of shape (i, m - i): the top i bits of x, then the top m - i bits of y.
uint64_t interval(uint32_t x, uint32_t y, int i, int m) {
  const uint64_t xi = i ? x >> (32 - i) : 0, yi = m - i ? y >> (32 - (m - i)) : 0;
  return (xi << (m - i)) | yi;
}

}  // namespace

bool is_02_net(const PointSet& ps, std::size_t first, std::size_t n) {
  if (ps.dim != 2 || n == 0 || !std::has_single_bit(n) || first + n > ps.size() || n > (std::size_t(1) << 31))
    return false;
  const int m = std::countr_zero(n);
  std::vector<uint8_t> seen(n);
  for (int i = 0; i <= m; ++i) {
    std::fill(seen.begin(), seen.end(), 0);
    for (std::size_t k = first; k < first + n; ++k) {
      auto q = ps.point(k);
      uint8_t& s = seen[interval(to_fixed(q[0]), to_fixed(q[1]), i, m)];
      if (s) return false;  // n points in n intervals: a repeat means an empty interval too
      s = 1;
    }
  }
  return true;
}

std::vector<bool> net_prefixes(const PointSet& ps) {
  std::vector<bool> out;
  for (std::size_t n = 1; n <= ps.size() && n <= (std::size_t(1) << 31); n *= 2) out.push_back(is_02_net(ps, 0, n));
  return out;
}

std::size_t stratum_breaks(const PointSet& ps) {
  if (ps.dim != 2) return 0;
  std::size_t breaks = 0;
  std::vector<std::vector<uint8_t>> seen;
  int level = -1;
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const int L = k == 0 ? 0 : int(std::bit_width(k));  // point k belongs to the 2^L prefix
    if (L > 31) break;
    if (L != level) {  // a new level: refill the bitmaps with the earlier points
      level = L;
      seen.assign(L + 1, std::vector<uint8_t>(std::size_t(1) << L, 0));
      for (std::size_t j = 0; j < k; ++j) {
        auto q = ps.point(j);
        for (int i = 0; i <= L; ++i) seen[i][interval(to_fixed(q[0]), to_fixed(q[1]), i, L)] = 1;
      }
    }
    auto q = ps.point(k);
    bool broke = false;
    for (int i = 0; i <= L; ++i) {
      uint8_t& s = seen[i][interval(to_fixed(q[0]), to_fixed(q[1]), i, L)];
      broke |= s != 0;
      s = 1;
    }
    breaks += broke;
  }
  return breaks;
}

}  // namespace pdrt
