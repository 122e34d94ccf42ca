#include "sampling/analysis/radial_spectrum.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pdrt {
namespace {

// Accumulates every non-DC periodogram sample into the annulus chosen by `bin_of(radius)`
// (negative = skipped), with two passes so the variance is computed about the exact mean.
template <class BinOf>
void accumulate(const Periodogram& pg, RadialSpectrum& rs, BinOf bin_of) {
  const int R = pg.resolution, h = R / 2;
  const int rows = pg.spectral_dim == 1 ? 1 : R;
  const std::size_t nb = rs.frequency.size();
  std::vector<double> sum(nb, 0.0), sq(nb, 0.0);
  rs.pixels.assign(nb, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (int y = 0; y < rows; ++y) {
      int ky = pg.spectral_dim == 1 ? 0 : y - h;
      for (int x = 0; x < R; ++x) {
        int kx = x - h;
        if (kx == 0 && ky == 0) continue;
        int b = bin_of(std::sqrt(double(kx) * kx + double(ky) * ky));
        if (b < 0) continue;
        double v = pg.power[std::size_t(y) * R + x];
        if (pass == 0) {
          sum[b] += v;
          ++rs.pixels[b];
        } else {
          double d = v - rs.power[b];
          sq[b] += d * d;
        }
      }
    }
    if (pass == 0) {
      rs.power.assign(nb, std::numeric_limits<double>::quiet_NaN());
      for (std::size_t b = 0; b < nb; ++b)
        if (rs.pixels[b] > 0) rs.power[b] = sum[b] / double(rs.pixels[b]);
    }
  }
  rs.variance.assign(nb, std::numeric_limits<double>::quiet_NaN());
  rs.anisotropy.assign(nb, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t b = 0; b < nb; ++b) {
    if (rs.pixels[b] == 0) continue;
    rs.variance[b] = sq[b] / double(rs.pixels[b]);
    if (rs.power[b] > 0.0) rs.anisotropy[b] = rs.variance[b] / (rs.power[b] * rs.power[b]);
  }
}

}  // namespace

RadialSpectrum equal_annuli(const Periodogram& pg, int annuli) {
  RadialSpectrum rs;
  const double corner = 0.5 * pg.resolution * std::sqrt(double(pg.spectral_dim));
  const double width = corner / annuli;
  for (int i = 0; i < annuli; ++i) {
    rs.inner.push_back(i * width);
    rs.outer.push_back((i + 1) * width);
    rs.frequency.push_back((i + 0.5) * width);
  }
  accumulate(pg, rs, [&](double r) { return std::min(int(r / width), annuli - 1); });
  return rs;
}

RadialSpectrum fine_annuli(const Periodogram& pg, int max_bins) {
  RadialSpectrum rs;
  const int last = pg.resolution / 2 - 1;  // outermost radius whose annulus is inside the square
  const int width = std::max(1, (last + max_bins - 1) / max_bins);
  const int bins = last / width;
  for (int b = 0; b < bins; ++b) {
    // Bin b covers [b*w + 0.5, (b+1)*w + 0.5): for w = 1, the pixels nearest radius b + 1.
    rs.inner.push_back(b * width + 0.5);
    rs.outer.push_back((b + 1) * width + 0.5);
    rs.frequency.push_back(0.5 * (rs.inner.back() + rs.outer.back()));
  }
  accumulate(pg, rs, [&](double r) {
    int b = int(std::floor((r - 0.5) / width));
    return r >= 0.5 && b < bins ? b : -1;
  });
  return rs;
}

double to_db(double x) {
  if (std::isnan(x) || x < 0.0) return std::numeric_limits<double>::quiet_NaN();
  return 10.0 * std::log10(x);
}

}  // namespace pdrt
