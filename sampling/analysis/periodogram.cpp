#include "sampling/analysis/periodogram.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace pdrt {
namespace {

// The FFTW planner is not thread-safe; execution is.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

}  // namespace

int spectral_dim_for(int dim) { return dim == 1 ? 1 : 2; }

int min_periodogram_resolution(int spectral_dim) { return spectral_dim == 1 ? 64 : 32; }
int max_periodogram_resolution(int spectral_dim) { return spectral_dim == 1 ? (1 << 24) : 4096; }

int default_periodogram_resolution(int spectral_dim, double count) {
  double want = 4.0 * std::pow(std::max(count, 1.0), 1.0 / spectral_dim);
  int r = min_periodogram_resolution(spectral_dim);
  while (r < want && r < max_periodogram_resolution(spectral_dim)) r *= 2;
  return r;
}

Periodogram compute_periodogram(std::span<const PointSet> sets, int resolution) {
  if (sets.empty()) throw std::invalid_argument("compute_periodogram: no point sets");
  const int sd = spectral_dim_for(sets.front().dim);
  const int R = resolution;
  if (R % 2 != 0 || R < min_periodogram_resolution(sd) || R > max_periodogram_resolution(sd))
    throw std::invalid_argument("compute_periodogram: bad resolution");
  Periodogram pg;
  pg.spectral_dim = sd;
  pg.resolution = R;
  const std::size_t rows = sd == 1 ? 1 : std::size_t(R);
  const std::size_t half = std::size_t(R / 2 + 1);  // r2c output width
  pg.power.assign(rows * std::size_t(R), 0.0);

  std::unique_ptr<double, FftwFree> in(static_cast<double*>(fftw_malloc(sizeof(double) * rows * R)));
  std::unique_ptr<fftw_complex, FftwFree> out(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * rows * half)));
  if (!in || !out) throw std::bad_alloc();
  fftw_plan plan;
  {
    std::lock_guard lock(planner_mutex());
    plan = sd == 1 ? fftw_plan_dft_r2c_1d(R, in.get(), out.get(), FFTW_ESTIMATE)
                   : fftw_plan_dft_r2c_2d(R, R, in.get(), out.get(), FFTW_ESTIMATE);
  }
  double total = 0.0;
  for (const PointSet& ps : sets) {
    const std::size_t n = ps.size();
    if (n == 0) continue;
    std::fill_n(in.get(), rows * R, 0.0);
    // McCool §2: an impulse is a value of 1 at the point's grid location.
    for (std::size_t i = 0; i < n; ++i) {
      auto p = ps.point(i);
      std::size_t ix = std::size_t(std::min(int(p[0] * R), R - 1));
      std::size_t iy = sd == 1 ? 0 : std::size_t(std::min(int(p[1] * R), R - 1));
      in.get()[iy * R + ix] += 1.0;
    }
    fftw_execute(plan);
    const double inv_n = 1.0 / double(n);
    const fftw_complex* F = out.get();
    // Expand the half spectrum with F(-k) = conj F(k) into the centred layout.
    for (std::size_t ky = 0; ky < rows; ++ky) {
      for (int kx = 0; kx < R; ++kx) {
        std::size_t sy = ky, sx = std::size_t(kx);
        if (sx >= half) sx = std::size_t(R) - sx, sy = (rows - ky) % rows;
        const double* z = F[sy * half + sx];
        double p = (z[0] * z[0] + z[1] * z[1]) * inv_n;
        int fx = kx < R / 2 ? kx : kx - R;
        int fy = sd == 1 ? 0 : (int(ky) < R / 2 ? int(ky) : int(ky) - R);
        std::size_t cy = sd == 1 ? 0 : std::size_t(fy + R / 2);
        pg.power[cy * R + std::size_t(fx + R / 2)] += p;
      }
    }
    total += double(n);
    ++pg.realizations;
  }
  {
    std::lock_guard lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
  if (pg.realizations == 0) throw std::invalid_argument("compute_periodogram: empty point sets");
  for (double& v : pg.power) v /= pg.realizations;
  // DC holds N: remove it so it does not dominate images and annuli.
  pg.power[(rows == 1 ? 0 : std::size_t(R / 2) * R) + std::size_t(R / 2)] = 0.0;
  pg.mean_count = total / pg.realizations;
  return pg;
}

}  // namespace pdrt
