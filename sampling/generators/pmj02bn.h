#pragma once
// `pmj02bn`: progressive multi-jittered (0,2) sequences with blue-noise selection (Christensen,
// Kensler & Kilpatrick, "Progressive Multi-Jittered Sample Sequences", EGSR 2018, §5-6), on the
// unit torus. From a prefix of 4^k points, the next 4^k each take the sub-square diagonally
// opposite an earlier point inside that point's 2^-k square, the 2 x 4^k after them one of the
// two sub-squares left (the farthest candidate decides which) and then its diagonal partner,
// so every 4^k square gains its points in the pmj order. Inside its sub-square a point must
// leave every elementary interval of its prefix's level empty; the x strata and the y strata
// that do are found independently (Pharr, "Efficient Generation of Points that Satisfy
// Two-Dimensional Elementary Intervals", JCGT 8(1), 2019), a candidate is a random valid x
// stratum, a random valid y stratum and uniform bits below them, and of `candidates` of them the
// one farthest from every earlier point (toroidal distance) is kept (Mitchell's best candidate).
// Every power-of-two prefix is therefore a (0,m,2)-net.
#include "sampling/core/point_set.h"

#include <cstdint>
#include <vector>

namespace pdrt {

inline constexpr int kPmj02bnDefaultCandidates = 10;  // Helmer's pmj-cpp uses 10 as well
inline constexpr int64_t kPmj02bnMaxCount = 65536;

// Points in generation order as 32-bit fixed point, x and y interleaved (2 * count values):
// value v stands for v / 2^32. Throws UsageError for count outside 1..65536 or candidates < 1.
std::vector<uint32_t> pmj02bn_fixed(int64_t count, uint64_t seed, int candidates = kPmj02bnDefaultCandidates);

// The same points as a periodic 2-D PointSet whose radius[i] is the minimum toroidal distance
// of the (i + 1)-prefix (+inf for one point).
PointSet pmj02bn(int64_t count, uint64_t seed, int candidates = kPmj02bnDefaultCandidates);

}  // namespace pdrt
