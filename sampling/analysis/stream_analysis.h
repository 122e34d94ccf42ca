#pragma once
// The samples a render actually took, seen as point sets: for one dimension family, each
// pixel's prefix [0, spp) of its bounce-0 stream (the camera's pixel, lens and time values and
// the first vertex's light and gloss values, which every camera sample takes). Reports the
// relative radius rho of every such prefix and their periodogram averaged over pixels
// (McCool & Fiume §2): the spectra of the samples a render used, not of the tables.
#include "sampling/analysis/radial_spectrum.h"
#include "sampling/samplers/sampler.h"

#include <vector>

namespace pdrt {

struct StreamAnalysis {
  Family family = Family::Pixel;
  int spp = 0, pixels = 0;  // points per set, sets analysed
  bool periodic = true;     // distances on the unit torus (all but the pixel family)
  // rho of each pixel's prefix: mean, 5th percentile and minimum (NaN below 2 points).
  double rho_mean = 0, rho_p05 = 0, rho_min = 0;
  int resolution = 0;       // periodogram grid
  RadialSpectrum spectrum;  // fine annuli; power 1 is white noise
};

// Up to `max_pixels` pixels of a width x height image, spread evenly over it (row-major
// stride), deterministic.
StreamAnalysis analyze_stream(const Sampler& sampler, Family family, int width, int height, int spp, int max_pixels);

}  // namespace pdrt
