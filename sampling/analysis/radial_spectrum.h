#pragma once
// Radial statistics of a periodogram (McCool & Fiume 1992 §2). Within each annulus: the mean
// power P_i and the variance s_i^2 of the periodogram values around it (variance *within* the
// annulus, not between realizations); anisotropy A_i = s_i^2 / P_i^2.
//
// Decibels: pdrt uses 10 log10 of these power-like ratios, so white noise (power 1) is 0 dB and
// a doubling is +3 dB. (McCool writes -20 log10 x; we keep the usual power convention.) For an
// average of K independent periodograms, white noise has anisotropy about 1/K, i.e.
// -10 log10 K dB, the reference level for "isotropic".
#include "sampling/analysis/periodogram.h"

#include <cstdint>
#include <vector>

namespace pdrt {

struct RadialSpectrum {
  std::vector<double> frequency;     // annulus centre radius, cycles per unit length
  std::vector<double> inner, outer;  // annulus bounds (inner inclusive)
  std::vector<int64_t> pixels;       // periodogram samples in the annulus (DC excluded)
  std::vector<double> power, variance, anisotropy;
};

// McCool's 20 (or `annuli`) equal-width annuli from DC to the corner of the periodogram,
// radius (R/2) sqrt(spectral_dim).
RadialSpectrum equal_annuli(const Periodogram& pg, int annuli = 20);

// PSA-style fine annuli inside the square: one pixel wide, centred on integer radii
// 1 .. R/2 - 1, unless that would exceed `max_bins` (long 1-D periodograms), in which case
// they are widened to the smallest whole number of pixels that fits.
RadialSpectrum fine_annuli(const Periodogram& pg, int max_bins = 2048);

// 10 log10(x); -inf for 0 and NaN for negative or NaN input.
double to_db(double x);

}  // namespace pdrt
