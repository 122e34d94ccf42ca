#pragma once
// Whether a square lies inside the union of two equal open disks: the 2-D pruning test that
// goes one step past Gamito–Maddock Appendix B (one disk) for the slivers between two disks.
#include <cmath>

namespace pdrt {

// True when the square [lo, lo + w]^2 lies inside the union of the open disks of squared
// radius r2 around a and b. The union of two disks has no holes, so the square is inside it
// exactly when its boundary is: each edge must be covered by the chords the disks cut from
// its line. Callers pass r2 shrunk by a relative margin (Gamito's in2_), so rounding can
// only keep a covered square, never drop an uncovered one.
inline bool square_in_two_disks(const double* lo, double w, const double* a, const double* b, double r2) {
  const double* disk[2] = {a, b};
  // First, without square roots: every corner must lie in one of the disks. Most squares
  // that reach this test fail here.
  bool corners = true;
  for (int c = 0; c < 4; ++c) {
    const double x = lo[0] + (c & 1) * w, y = lo[1] + (c >> 1) * w;
    const double da = (x - a[0]) * (x - a[0]) + (y - a[1]) * (y - a[1]);
    const double db = (x - b[0]) * (x - b[0]) + (y - b[1]) * (y - b[1]);
    corners &= (da < r2) | (db < r2);
  }
  if (!corners) return false;
  for (int e = 0; e < 4; ++e) {
    const int along = e & 1, across = 1 - along;  // the edge runs along axis `along`
    const double at = lo[across] + (e >> 1) * w, from = lo[along], to = lo[along] + w;
    double s[2], t[2];  // each disk's open chord (s, t) on the edge's line; empty when s == t
    for (int q = 0; q < 2; ++q) {
      const double off = at - disk[q][across], rest = r2 - off * off;
      const double half = rest > 0.0 ? std::sqrt(rest) : 0.0;
      s[q] = disk[q][along] - half, t[q] = disk[q][along] + half;
    }
    const int p = s[0] <= s[1] ? 0 : 1, q = 1 - p;  // s[p] <= s[q]
    const bool alone = (s[p] < from && t[p] > to) || (s[q] < from && t[q] > to);
    // Otherwise the earlier chord must hold the start and the later one take over from it.
    if (!alone && !(s[p] < from && t[p] > from && s[q] < t[p] && t[q] > to)) return false;
  }
  return true;
}

}  // namespace pdrt
