#include "renderer/compare/error_spectrum.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace pdrt {

namespace {

std::mutex& planner_mutex() {
  static std::mutex m;  // FFTW's planner is not thread-safe
  return m;
}

// Signed frequency in cycles per pixel of index k of an n-point DFT.
double signed_frequency(int k, int n) { return (k <= n / 2 ? k : k - n) / double(n); }

}  // namespace

std::vector<double> luminance_error(const Image& t, const Image& r) {
  if (t.width != r.width || t.height != r.height || t.rgb.size() != r.rgb.size())
    throw std::invalid_argument("error spectrum: images differ in size");
  std::vector<double> e(std::size_t(t.width) * t.height);
  for (std::size_t i = 0; i < e.size(); ++i) {
    const float* a = &t.rgb[3 * i];
    const float* b = &r.rgb[3 * i];
    e[i] = double(luminance(Vec3(a[0], a[1], a[2]))) - luminance(Vec3(b[0], b[1], b[2]));
  }
  return e;
}

std::vector<double> power_spectrum(const std::vector<double>& e, int W, int H) {
  if (W < 1 || H < 1 || e.size() != std::size_t(W) * H) throw std::invalid_argument("power_spectrum: bad size");
  const int half = W / 2 + 1;
  struct Free {
    void operator()(void* p) const { fftw_free(p); }
  };
  std::unique_ptr<double, Free> in(static_cast<double*>(fftw_malloc(sizeof(double) * e.size())));
  std::unique_ptr<fftw_complex, Free> out(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * std::size_t(H) * half)));
  fftw_plan plan;
  {
    std::lock_guard lock(planner_mutex());
    plan = fftw_plan_dft_r2c_2d(H, W, in.get(), out.get(), FFTW_ESTIMATE);
  }
  std::copy(e.begin(), e.end(), in.get());
  fftw_execute(plan);
  {
    std::lock_guard lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
  std::vector<double> p(e.size());
  const double norm = 1.0 / (double(W) * H);
  for (int ky = 0; ky < H; ++ky)
    for (int kx = 0; kx < W; ++kx) {
      // Columns past W / 2 are the conjugate mirrors of the half plane FFTW returns.
      const bool mirrored = kx >= half;
      const int sx = mirrored ? W - kx : kx, sy = mirrored ? (H - ky) % H : ky;
      const double* z = out.get()[std::size_t(sy) * half + sx];
      p[std::size_t(ky) * W + kx] = (z[0] * z[0] + z[1] * z[1]) * norm;
    }
  return p;
}

RadialSpectrum radial_spectrum(const std::vector<double>& power, int W, int H) {
  const int bins = std::max(1, std::min(W, H) / 2);
  RadialSpectrum s;
  s.frequency.resize(bins), s.power.assign(bins, 0.0);
  std::vector<double> count(bins, 0.0);
  for (int ky = 0; ky < H; ++ky) {
    const double fy = signed_frequency(ky, H);
    for (int kx = 0; kx < W; ++kx) {
      const double fx = signed_frequency(kx, W), f = std::sqrt(fx * fx + fy * fy);
      if (f == 0 || f > 0.5) continue;  // DC is the mean error; corners beyond 0.5 are partial rings
      const int b = std::min(bins - 1, int(f * 2 * bins));
      s.power[b] += power[std::size_t(ky) * W + kx];
      count[b] += 1;
    }
  }
  for (int b = 0; b < bins; ++b) {
    s.frequency[b] = (b + 0.5) / (2.0 * bins);
    if (count[b] > 0) s.power[b] /= count[b];
  }
  return s;
}

RadialSpectrum error_spectrum(const Image& t, const Image& r) {
  return radial_spectrum(power_spectrum(luminance_error(t, r), t.width, t.height), t.width, t.height);
}

PowerSplit split_power(const std::vector<double>& power, int W, int H, double cutoff) {
  PowerSplit s;
  for (int ky = 0; ky < H; ++ky) {
    const double fy = signed_frequency(ky, H);
    for (int kx = 0; kx < W; ++kx) {
      const double fx = signed_frequency(kx, W), p = power[std::size_t(ky) * W + kx];
      s.total += p;
      if (fx * fx + fy * fy < cutoff * cutoff) s.low += p;
    }
  }
  return s;
}

double low_frequency_share(const PowerSplit& s, const PowerSplit& noise) {
  const double total = s.total - noise.total;
  if (!(total > 0)) return std::nan("");
  return std::clamp((s.low - noise.low) / total, 0.0, 1.0);
}

double low_frequency_share(const Image& t, const Image& r, const PowerSplit& noise) {
  return low_frequency_share(split_power(power_spectrum(luminance_error(t, r), t.width, t.height), t.width, t.height),
                             noise);
}

PowerSplit reference_noise_power(const Image& a, int na, const Image& b, int nb) {
  const double n = double(na) + nb, w = double(na) * nb / (n * n);
  PowerSplit s = split_power(power_spectrum(luminance_error(a, b), a.width, a.height), a.width, a.height);
  s.low *= w, s.total *= w;
  return s;
}

}  // namespace pdrt
