#pragma once
// `stratified-bc`: a 1-D progressive jitter whose new point is the best of several
// candidates (issue 16, the time family's stratified variant). Point j >= 2^k goes into the
// half of its parent's (point j - 2^k) cell at the 2^(k+1) grid that the parent does not
// occupy, as in progressive jitter (Christensen et al. 2018), so every 2^k prefix has exactly
// one point per 1/2^k stratum; inside that half it takes, of m uniform candidates, the one
// farthest from every earlier point (Mitchell's best candidate), which raises the minimum
// distance of every prefix far above jitter's.
#include "sampling/core/point_set.h"

#include <cstdint>

namespace pdrt {

struct StratifiedBestCandidate1D {
  int64_t count = 1024;
  uint64_t seed = 1;
  int candidates = 16;   // m per point
  bool periodic = true;  // distances on the circle (tables); else on [0, 1)
};

// Points in [0, 1) in generation order; radius[i] is the minimum distance of the (i+1)-prefix
// (non-increasing; +inf for one point). Throws UsageError for count < 1 or candidates < 1.
PointSet stratified_best_candidate_1d(const StratifiedBestCandidate1D& p);

}  // namespace pdrt
