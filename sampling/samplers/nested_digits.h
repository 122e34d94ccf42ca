#pragma once
// The sample part of a screen-space index (Ahmed & Wonka 2020 §4, as `zsobol` and `poisson-ss`
// use it): the m low bits of a pixel's block as base-4 digits from the top, each permuted by
// its node's permutation (a node: the index bits above the digit), and for odd m a last single
// bit. Written for a window of indices a bottom node at a time (the lowest base-4 digit's
// 4 << (m & 1) indices): the digits above a node are kept while its parent stays, so a value
// costs a lookup, an or and a store, where walking the levels per value cost 2-3 points of a
// render's CPU.
#include <cstdint>

namespace pdrt {

// out[i - a] = top | the digits of i, for a <= i < e < 2^m. perm(l, node) is the permutation of
// level l's node (level 0 the top digit, at shift m - 2; node = i >> (m - 2l)), indexable by the
// digit (0..3) and giving its image; tail(i), for odd m, is the last bit of i. Callers keep
// their own caches of permutations and flips: the walk asks perm for every bottom node and, per
// parent, for the levels above.
template <class Perm, class Tail>
void nested_digits(int m, uint32_t top, uint32_t a, uint32_t e, Perm&& perm, Tail&& tail, uint32_t* out) {
  const int b = m & 1, L = m / 2;  // the tail bit below the base-4 digits, and those digits
  if (L == 0) {
    for (uint32_t i = a; i < e; ++i) out[i - a] = top | (b ? tail(i) : 0u);
    return;
  }
  const int w = 2 + b;  // index bits below a bottom node
  uint32_t above = 0, parent = UINT32_MAX, parent_digit[4] = {0, 0, 0, 0};
  for (uint32_t n = a >> w; uint64_t(n) << w < e; ++n) {
    if (L > 1 && n >> 2 != parent) {  // the levels above the bottom node's own digit
      parent = n >> 2, above = 0;
      for (int l = 0; l < L - 2; ++l) {
        const int up = 2 * (L - 1 - l);  // level l's node of bottom node n: n >> up
        above |= uint32_t(perm(l, n >> up)[(n >> (up - 2)) & 3u]) << (m - 2 - 2 * l);
      }
      const auto& p = perm(L - 2, parent);
      for (uint32_t d = 0; d < 4; ++d) parent_digit[d] = uint32_t(p[d]);
    }
    const uint32_t upper = top | (L > 1 ? above | (parent_digit[n & 3u] << w) : 0u);
    const auto& bottom = perm(L - 1, n);
    const uint32_t lo = n << w > a ? n << w : a;
    const uint32_t hi = (uint64_t(n) + 1) << w < e ? uint32_t((uint64_t(n) + 1) << w) : e;
    for (uint32_t i = lo; i < hi; ++i) out[i - a] = upper | (uint32_t(bottom[(i >> b) & 3u]) << b) | (b ? tail(i) : 0u);
  }
}

}  // namespace pdrt
