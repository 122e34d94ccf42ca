#pragma once
// Where on screen the error sits: the power spectrum of the luminance error image
// Y(render) - Y(reference), radially averaged (white error is flat, blue-noise error has
// little power at low frequencies), as a whole 2-D plane (averaged over seeds for the report's
// spectrum images), and the share of its power below 1/4 cycle per pixel, the frequencies the
// eye resolves at a normal viewing distance.
#include "renderer/render/film.h"
#include "sampling/analysis/radial_spectrum.h"

#include <vector>

namespace pdrt {

// The low-frequency share's radius in cycles per pixel.
inline constexpr double kLowFrequencyCutoff = 0.25;

// Per pixel (row-major), Y(test) - Y(reference), Y the Rec. 709 luminance.
std::vector<double> luminance_error(const Image& test, const Image& reference);

// The periodogram |F(e)|^2 / (W H) of the W x H field `e` (row-major, no window: the field is
// taken as one period) over the whole frequency plane: W x H values, row ky, column kx, the DC
// term at (0, 0); index k stands for k / W cycles per pixel up to W / 2, then (k - W) / W. By
// Parseval the values sum to sum(e^2), so the spectrum of the error has the MSE times W H.
std::vector<double> power_spectrum(const std::vector<double>& e, int W, int H);

// `power` (a W x H power_spectrum) averaged over rings of radial frequency |f| in (0, 0.5]:
// min(W, H) / 2 equal-width bins, `frequency` their centres in cycles per pixel, `power` the
// mean in each bin (other fields left empty). DC (the mean error) and the corners beyond 0.5,
// partial rings, are left out.
RadialSpectrum radial_spectrum(const std::vector<double>& power, int W, int H);

// radial_spectrum of the luminance error's power_spectrum.
RadialSpectrum error_spectrum(const Image& test, const Image& reference);

// Sums of a power spectrum: over |f| < cutoff and over the whole plane, the DC term in both.
struct PowerSplit {
  double low = 0, total = 0;
};
PowerSplit split_power(const std::vector<double>& power, int W, int H, double cutoff = kLowFrequencyCutoff);

// The share of the luminance error's power at radial frequency |f| < kLowFrequencyCutoff:
// (low - noise.low) / (total - noise.total), `noise` the reference's own noise spectrum (the
// power the reference adds to every error in expectation, as for the RMSE), clamped to [0, 1];
// NaN when nothing is left of the total. The DC term (the mean error, i.e. bias) is included in
// both sums, so the share splits the MSE itself (Parseval) and a biased image's offset counts as
// low-frequency error. White error gives the area of the disc, pi r^2 = pi / 16 ~= 0.196.
double low_frequency_share(const Image& test, const Image& reference, const PowerSplit& noise = {});
// The same from the error's split power.
double low_frequency_share(const PowerSplit& error, const PowerSplit& noise);

// The reference's noise spectrum from its halves a, b of na and nb samples per pixel: the power
// of Y(a) - Y(b) times na nb / (na + nb)^2 (as reference_noise in seed_statistics.h), split.
PowerSplit reference_noise_power(const Image& a, int na, const Image& b, int nb);

}  // namespace pdrt
