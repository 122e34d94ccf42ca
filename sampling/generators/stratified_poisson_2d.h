#pragma once
// `stratified-pd`: a "(0,2)-first" hierarchical Poisson-disk sequence on the unit torus
// (issue 16; design study ../shared/research/stratified-pd.md, "bar-02-bc"). Point n belongs
// to the 2^L prefix, L = bit_width(n). Its candidates are the cells left free by every
// elementary interval of level L (the one admissible cell of each open interval of the most
// square shape: the bits below it are forced, Christensen et al. 2018 §4); of up to m such
// candidates the one farthest from every earlier point is kept (Mitchell's best candidate).
// When none keeps the minimum-distance floor of issue 3, rho(n) >= max(prefix_floor,
// whole_floor sqrt(n/N)) on every prefix of >= 16 points, the most elongated interval shapes
// (1-D strata first, squares last) are dropped one level at a time, then all strata (plain
// best candidate). So every prefix is Poisson-disk at the floor, and stratified wherever the
// floor allows.
#include "sampling/core/point_set.h"

#include <cstdint>

namespace pdrt {

struct StratifiedPoisson2D {
  int64_t count = 2048;
  uint64_t seed = 1;
  int candidates = 64;         // m: open intervals tried per point
  double prefix_floor = 0.65;  // rho floor on every prefix of >= first_prefix points
  double whole_floor = 0.72;   // rho of the whole set (reached through whole_floor sqrt(n/N))
  int64_t first_prefix = 16;   // smaller prefixes get no floor
};

// Points on the torus in generation order, coordinates exact 32-bit fixed point; radius[i]
// is the minimum distance of the (i+1)-prefix (+inf for one point). Throws UsageError for
// count outside 1..2^20, candidates < 1 or floors outside [0, 1].
PointSet stratified_poisson_2d(const StratifiedPoisson2D& p);

}  // namespace pdrt
