#pragma once
// Periodogram of point sets seen as impulses, after McCool & Fiume 1992 §2: each set is
// splatted as unit impulses on an R×R grid (nearest cell; the grid tiles the plane
// periodically), transformed with FFTW, and |F(k)|^2 / N is averaged over the realizations.
// Normalised by N, a Poisson process has expected power 1 at every k != 0 (0 dB); DC (= N) is
// set to 0. Sets of dim > 2 are analysed through their (x0, x1) projection; 1-D sets give a
// 1-D periodogram.
#include "sampling/core/point_set.h"

#include <span>
#include <vector>

namespace pdrt {

struct Periodogram {
  int spectral_dim = 2;  // 1 or 2
  int resolution = 0;    // R: the grid is R (1-D) or R×R (2-D)
  int realizations = 0;
  double mean_count = 0.0;  // mean N over the realizations
  // Centred layout: frequency (kx, ky) in [-R/2, R/2) is at (ky + R/2) * R + (kx + R/2)
  // (2-D) or kx + R/2 (1-D), in cycles per unit length.
  std::vector<double> power;

  double at(int kx, int ky = 0) const {
    std::size_t h = std::size_t(resolution / 2);
    return spectral_dim == 1 ? power[std::size_t(kx) + h]
                             : power[(std::size_t(ky + int(h))) * std::size_t(resolution) + std::size_t(kx) + h];
  }
};

// 1 for 1-D sets, 2 otherwise.
int spectral_dim_for(int dim);

// Resolution limits per spectral dimension (even sizes; kept so 20 annuli are >= 1 pixel wide).
int min_periodogram_resolution(int spectral_dim);
int max_periodogram_resolution(int spectral_dim);

// Smallest power of two >= 4 N^(1/d) within the limits: the Nyquist frequency R/2 is then about
// twice the mean-spacing frequency N^(1/d), where a Poisson-disk spectrum has its peak. For
// N = 64 in 2-D this is McCool's 32×32.
int default_periodogram_resolution(int spectral_dim, double count);

// Averaged periodogram of `sets` (all of the same dim) at resolution R (even, within limits).
Periodogram compute_periodogram(std::span<const PointSet> sets, int resolution);

}  // namespace pdrt
