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
  // Flips of the scramble-tree nodes above this depth are optimised, 1..16; deeper ones are
  // hashed from the seed. Below ceil(log2 count) a level's points get part of their cell bits
  // at random (2048 points: worst prefix rho 0.40 at depth 10, 0.42 at 11).
  int depth = 10;
  // Annealing proposals per optimised node (a node moves 2^(m-k) points at depth k).
  int sweeps = 24;
  // Soft-min sharpness: every pair of a level closer than rho 0.93 adds exp(-beta rho) to the
  // energy, i.e. exp(-beta s) of each point's soft nearest-neighbour score s (120 is worse:
  // only the single worst pair is seen).
  double beta = 60.0;
  // Start temperature, in the soft-min's rho units; it falls geometrically to 1/1000 of it.
  double temperature = 0.01;
  // Then a sharper, colder pass (temperature / 10) on the worst pairs: 1024 points, 64 seeds,
  // worst prefix rho mean 0.443 with 32 plain sweeps, 0.448 with 24 + 8 polish sweeps.
  int polish_sweeps = 8;
  double polish_beta = 90.0;
  // Pairs of level L (the prefix 2^L) weigh 2^(level_weight (m - L)): 1 gives every level the
  // same total weight. With 0 (every point alike) the 8 points of level 4 count for little
  // against the 512 of level 10 and the worst prefix is nearly always one of n = 16..128
  // (1024 points: worst prefix rho mean 0.425 at 0, 0.445 at 1).
  double level_weight = 1.0;
};

// 2-D points in [0,1)^2 on the torus at 32-bit fixed point, in generation order; radius[i] is
// the minimum toroidal distance of the (i+1)-prefix (+inf for one point). Throws UsageError
// naming the argument for count outside 1..65536, depth outside 1..16, (polish_)sweeps < 0,
// (polish_)beta outside (0, 1000], temperature < 0 or level_weight outside [0, 4].
PointSet owen_poisson_2d(const OwenPoisson2D& p);

}  // namespace pdrt
