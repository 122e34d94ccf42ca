// Spectral signatures of the generators, measured as McCool & Fiume 1992 §2 do: the
// periodogram averaged over K realizations, reduced to radial power (dB, 10 log10, white
// noise = 0 dB). Frequencies are in units of the mean sample spacing (f / sqrt(N)).
#include "sampling/generators/generator.h"
#include "sampling/analysis/periodogram.h"
#include "sampling/analysis/radial_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

using namespace pdrt;

namespace {

constexpr int kRealizations = 8;
constexpr int64_t kCount = 4096;

struct Spectrum {
  RadialSpectrum fine;  // one-pixel annuli
  double unit = 1.0;    // sqrt(mean N): frequency / unit = cycles per mean sample spacing
};

Spectrum spectrum_of(const std::string& method) {
  std::vector<PointSet> sets;
  double mean = 0.0;
  for (int s = 0; s < kRealizations; ++s) {
    GeneratorParams p;
    p.method = method;
    p.dim = 2;
    p.count = kCount;
    p.seed = 1000 + uint64_t(s);
    p.periodic = true;  // the periodogram tiles the square (McCool §2, assumption 4)
    sets.push_back(generate(p));
    mean += double(sets.back().size()) / kRealizations;
  }
  Periodogram pg = compute_periodogram(sets, default_periodogram_resolution(2, mean));
  return {fine_annuli(pg), std::sqrt(pg.mean_count)};
}

// Pixel-weighted mean power of the annuli with normalised frequency in [lo, hi).
double band_power(const Spectrum& s, double lo, double hi) {
  double sum = 0.0, pixels = 0.0;
  for (std::size_t i = 0; i < s.fine.power.size(); ++i) {
    double f = s.fine.frequency[i] / s.unit;
    if (f >= lo && f < hi) sum += s.fine.power[i] * double(s.fine.pixels[i]), pixels += double(s.fine.pixels[i]);
  }
  return sum / pixels;
}

// The blue-noise peak: the 0.1-wide band with the most power between 0.5 and 2 spacings^-1.
double peak_frequency(const Spectrum& s) {
  double best_f = 0.0, best = -1.0;
  for (double f = 0.5; f < 2.0; f += 0.025) {
    double p = band_power(s, f - 0.05, f + 0.05);
    if (p > best) best = p, best_f = f;
  }
  return best_f;
}

// Criterion for a Poisson-disk gap: below half its peak frequency (a disk of radius r
// suppresses wavelengths longer than about 2r, McCool §3.2 / Fig. 9) the mean power is at
// least 5 dB under white noise, and the peak itself rises above white noise.
void expect_low_frequency_gap(const std::string& method) {
  Spectrum s = spectrum_of(method);
  double fp = peak_frequency(s);
  double low = to_db(band_power(s, 0.0, 0.5 * fp));
  double peak = to_db(band_power(s, fp - 0.05, fp + 0.05));
  EXPECT_LT(low, -5.0) << method << ": peak at " << fp << " spacings^-1";
  EXPECT_GT(peak, 0.5) << method;
}

}  // namespace

TEST(Spectra, RandomHasFlatUnitRadialPower) {
  Spectrum s = spectrum_of("random");
  // Bands 0.25 spacings^-1 wide hold >= ~500 independent values per realization, so the
  // standard error is < 0.1 dB; 0.5 dB is a > 5-sigma bound.
  for (double f = 0.05; f + 0.25 <= 2.0; f += 0.25) EXPECT_NEAR(to_db(band_power(s, f, f + 0.25)), 0.0, 0.5) << f;
  EXPECT_NEAR(to_db(band_power(s, 0.05, 2.0)), 0.0, 0.15);
}

TEST(Spectra, GamitoHasLowFrequencyGap) { expect_low_frequency_gap("gamito"); }

TEST(Spectra, DartHasLowFrequencyGap) { expect_low_frequency_gap("dart"); }

TEST(Spectra, JitterLiesBetweenRandomAndDartAtLowFrequency) {
  // Low band 0.1..0.5 spacings^-1: white for random, partly suppressed for jitter (power
  // 1 - |sinc|^2 of the cell jitter), strongly suppressed for dart throwing.
  double random = band_power(spectrum_of("random"), 0.1, 0.5);
  double jitter = band_power(spectrum_of("jitter"), 0.1, 0.5);
  double dart = band_power(spectrum_of("dart"), 0.1, 0.5);
  EXPECT_LT(to_db(jitter), to_db(random) - 3.0) << "jitter " << jitter << " random " << random;
  EXPECT_GT(to_db(jitter), to_db(dart) + 1.0) << "jitter " << jitter << " dart " << dart;
}

namespace {

// Mean power on the ring of the spectral peak (normalised frequency 0.9..1.2) within
// ±`half_width_deg` of the given angles, over the mean of the whole ring.
double sector_ratio(const Periodogram& pg, std::vector<double> angles_deg, double half_width_deg) {
  const double unit = std::sqrt(pg.mean_count);
  const int h = pg.resolution / 2;
  double ring = 0.0, sector = 0.0;
  int n_ring = 0, n_sector = 0;
  for (int ky = -h; ky < h; ++ky)
    for (int kx = -h; kx < h; ++kx) {
      double f = std::hypot(double(kx), double(ky)) / unit;
      if (f < 0.9 || f >= 1.2) continue;
      double p = pg.at(kx, ky);
      ring += p, ++n_ring;
      double a = std::atan2(double(ky), double(kx)) * 180.0 / M_PI;
      for (double c : angles_deg) {
        double d = std::remainder(a - c, 360.0);
        if (std::abs(d) <= half_width_deg) {
          sector += p, ++n_sector;
          break;
        }
      }
    }
  return (sector / n_sector) / (ring / n_ring);
}

Periodogram mccool_periodogram(std::optional<int64_t> attempts, std::optional<double> start_radius = std::nullopt) {
  std::vector<PointSet> sets;
  for (int s = 0; s < kRealizations; ++s) {
    GeneratorParams p;
    p.method = "mccool";
    p.count = kCount;
    p.seed = 2000 + uint64_t(s);
    p.periodic = true;
    p.attempts = attempts;
    p.start_radius = start_radius;
    sets.push_back(generate(p));
  }
  return compute_periodogram(sets, default_periodogram_resolution(2, double(kCount)));
}

}  // namespace

TEST(Spectra, McCoolRingHasNoSquareLatticePeaks) {
  // Starting from the domain's diameter and filling every radius step completely (an
  // unlimited miss budget) grows a square lattice whose peaks sit on the axes and diagonals
  // of the ring. The defaults must keep the ring even: those sectors within 1.5x (1.8 dB)
  // of the ring mean.
  double ratio = sector_ratio(mccool_periodogram(std::nullopt), {0, 45, 90, 135, 180, 225, 270, 315}, 4.0);
  RecordProperty("sector_ratio", std::to_string(ratio));
  EXPECT_LT(ratio, 1.5);
}

TEST(Spectra, SectorRatioDetectsTheLatticeOfUnlimitedBudget) {
  // The detector itself: the saturating variant started at the diameter of the torus
  // (sqrt(2)/2) must show the peaks.
  double ratio =
      sector_ratio(mccool_periodogram(int64_t(1) << 40, std::sqrt(0.5)), {0, 45, 90, 135, 180, 225, 270, 315}, 4.0);
  RecordProperty("sector_ratio", std::to_string(ratio));
  EXPECT_GT(ratio, 1.5);
}
