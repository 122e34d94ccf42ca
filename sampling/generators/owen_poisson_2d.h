#pragma once
// `owen-pd`: a strictly stratified 2-D Poisson-disk family (issue 16 item 2; study:
// /work/shared/research/stratified-pd.md, "owen-opt"). The points are the 2-D Sobol sequence
// (van der Corput, then the second Sobol dimension) under a nested uniform (Owen 1995)
// scramble whose shallow flip bits are annealed for a large minimum distance in every
// power-of-two prefix; each level [2^(L-1), 2^L) is then put in farthest-point order. Every
// flip keeps it an Owen scramble, so every power-of-two prefix stays a (0,m,2)-net (the
// study's "key structural fact": for a (0,2) sequence the flips are the whole design space).
#include "sampling/core/point_set.h"

#include <cstdint>

namespace pdrt {

struct OwenPoisson2D {
  int64_t count = 1024;  // 1..65536; the first `count` of 2^ceil(log2 count) points
  uint64_t seed = 1;
  int depth = 10;  // flips of the scramble-tree nodes above this depth are optimised, 1..16
  // Annealing proposals per optimised node (a node moves 2^(m-k) points at depth k).
  int sweeps = 32;
  // Soft-min sharpness: the objective is sum exp(-beta * score) over the points.
  double beta = 60.0;
  // Start temperature, in the soft-min's rho units; it falls geometrically to ~0.
  double temperature = 0.01;
};

// 2-D points in [0,1)^2 on the torus at 32-bit fixed point, in generation order; radius[i] is
// the minimum toroidal distance of the (i+1)-prefix (+inf for one point). Throws UsageError
// naming the argument for count outside 1..65536, depth outside 1..16, sweeps < 0, beta <= 0
// or temperature < 0.
PointSet owen_poisson_2d(const OwenPoisson2D& p);

}  // namespace pdrt
