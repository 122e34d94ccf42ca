#pragma once
// Uniformity of 1-D point sets on the circle. A Poisson-disk radius says nothing about how
// evenly the density spreads at large scales; McCool–Fiume relaxation in 1-D keeps the
// radius but not the density (docs/results.md), and discrepancy is what exposes it.
#include <vector>

namespace pdrt {

// Kuiper's statistic V = max(F_n - F) + max(F - F_n) of values in [0, 1): the largest
// deviation of the empirical from the uniform measure over all arcs of the circle, so it
// does not depend on where the circle is cut (tables are toroidal). 1/n for a lattice,
// about 1 when all points coincide; 0 for an empty set.
double periodic_discrepancy_1d(std::vector<double> values);

}  // namespace pdrt
