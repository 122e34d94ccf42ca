#pragma once
// (0,m,2)-nets in base 2 (Niederreiter; Christensen et al. 2018 §2): 2^m points such that
// every elementary interval [a 2^-i, (a+1) 2^-i) x [b 2^-(m-i), (b+1) 2^-(m-i)), i = 0..m,
// holds exactly one point.
#include "sampling/core/point_set.h"

#include <cstddef>
#include <vector>

namespace pdrt {

// Whether points [first, first + n) of a 2-D set form a (0,m,2)-net, n = 2^m (false when n
// is not a power of two or the set is too short). Coordinates are judged at 32-bit fixed point.
bool is_02_net(const PointSet& points, std::size_t first, std::size_t n);

// For m = 0, 1, ... while 2^m <= size: whether the prefix of 2^m points is a (0,m,2)-net.
std::vector<bool> net_prefixes(const PointSet& points);

// Points of the 2^ceil(log2(i+1)) prefix that share an elementary interval of that prefix's
// shapes with an earlier point: point i "breaks a stratum" when, for some shape of level
// L = ceil(log2(i+1)), an earlier point lies in the same interval. Counts such points.
std::size_t stratum_breaks(const PointSet& points);

}  // namespace pdrt
