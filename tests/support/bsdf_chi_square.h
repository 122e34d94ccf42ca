#pragma once
// Chi-square goodness of fit of a BSDF's sample() against its pdf() (after pbrt-v3's and
// Mitsuba's test), shared by the BSDF tests: directions binned in (cos theta, phi), expected
// counts from adaptive Simpson quadrature of pdf(), delta samples and failed samples each a
// category of their own.
#include "renderer/render/bsdf.h"
#include "sampling/analysis/incomplete_gamma.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pdrt::test {

// Rng::uniform() is a double in [0, 1); rounding to float can give 1.0f, which is out of range.
inline float uniform_float(Rng& rng) { return std::min(float(rng.uniform()), 0x1.fffffep-1f); }

inline double rel_diff(double a, double b) { return std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

constexpr int kCosBins = 20, kPhiBins = 40;

inline Vec3 from_theta_phi(double theta, double phi) {
  return {float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))};
}

// Integral of f over [x0,x1]x[y0,y1] by adaptive tensor-product Simpson: one 3x3 rule against
// four, split where they disagree (Richardson-corrected on acceptance). Agreement is absolute
// (eps) or relative (rel: for the chi-square bins 1e-4 is above the float noise of a peaked pdf,
// which would otherwise force refinement to the depth limit, and ~0.01 sigma of any bin count).
template <class F>
double simpson3x3(F& f, double x0, double x1, double y0, double y1) {
  const double w[3] = {1, 4, 1};
  double s = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += w[i] * w[j] * f(x0 + 0.5 * i * (x1 - x0), y0 + 0.5 * j * (y1 - y0));
  return s * (x1 - x0) * (y1 - y0) / 36.0;
}

template <class F>
double adaptive_simpson(F& f, double x0, double x1, double y0, double y1, double whole, double eps, double rel,
                        int depth) {
  double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
  double q[4] = {simpson3x3(f, x0, xm, y0, ym), simpson3x3(f, xm, x1, y0, ym), simpson3x3(f, x0, xm, ym, y1),
                 simpson3x3(f, xm, x1, ym, y1)};
  double halves = q[0] + q[1] + q[2] + q[3];
  if (depth == 0 || std::abs(halves - whole) <= 15.0 * std::max(eps, rel * std::abs(halves)))
    return halves + (halves - whole) / 15.0;
  return adaptive_simpson(f, x0, xm, y0, ym, q[0], eps / 4, rel, depth - 1) +
         adaptive_simpson(f, xm, x1, y0, ym, q[1], eps / 4, rel, depth - 1) +
         adaptive_simpson(f, x0, xm, ym, y1, q[2], eps / 4, rel, depth - 1) +
         adaptive_simpson(f, xm, x1, ym, y1, q[3], eps / 4, rel, depth - 1);
}

struct FitResult {
  double statistic = 0, dof = 0, p = 0;
  double pdf_integral = 0;       // of pdf() over the sphere
  double success_fraction = 0;   // of sample() calls returning true
  int64_t zero_pdf_samples = 0;  // successful samples where pdf() is 0 (must never happen)
  int64_t pdf_mismatches = 0;    // samples whose pdf differs from pdf() by > 1e-3 relative
  double delta_probability = 0;  // the discrete probability delta samples report (their own category)
  int64_t delta_mismatches = 0;  // delta samples reporting another probability than the first one
};

// B: Bsdf, or anything with its sample() and pdf() (a mix material's routine, test_mix_material.cpp).
template <class B>
FitResult chi_square_fit(const B& bsdf, const Vec3& wo, uint64_t seed, int64_t n) {
  FitResult r;
  // The bins, then the delta lobe's category, then the failures'.
  std::vector<double> observed(kCosBins * kPhiBins + 2, 0.0), expected(observed.size(), 0.0);
  Rng rng(seed);
  int64_t successes = 0;
  for (int64_t i = 0; i < n; ++i) {
    float u1 = uniform_float(rng), u2 = uniform_float(rng), uc = uniform_float(rng);
    BsdfSample s;
    if (!bsdf.sample(wo, u1, u2, uc, &s)) continue;
    ++successes;
    if (s.delta) {
      // A delta lobe: one category, expected with the probability the sample reports.
      if (r.delta_probability == 0) r.delta_probability = s.pdf;
      r.delta_mismatches += rel_diff(s.pdf, r.delta_probability) > 1e-6;
      observed[observed.size() - 2] += 1;
      continue;
    }
    float p = bsdf.pdf(wo, s.wi);
    r.zero_pdf_samples += p == 0;
    r.pdf_mismatches += rel_diff(p, s.pdf) > 1e-3;
    double phi = std::atan2(double(s.wi.y), double(s.wi.x));
    if (phi < 0) phi += 2 * M_PI;
    int ic = std::clamp(int((double(s.wi.z) + 1.0) * 0.5 * kCosBins), 0, kCosBins - 1);
    int ip = std::clamp(int(phi / (2 * M_PI) * kPhiBins), 0, kPhiBins - 1);
    observed[ic * kPhiBins + ip] += 1;
  }
  observed.back() = double(n - successes);  // failures are a category of their own
  r.success_fraction = double(successes) / double(n);

  // Expected counts: pdf integrated over each (cos theta, phi) bin. The quadrature runs in
  // (theta, phi) with the sin theta Jacobian, which is smooth at the poles where pdf(cos, phi)
  // has a square-root singularity. Each bin starts as 2x2 cells so that a narrow lobe inside a
  // bin is seen before adaptivity decides.
  auto f = [&](double theta, double phi) { return double(bsdf.pdf(wo, from_theta_phi(theta, phi))) * std::sin(theta); };
  const double dc = 2.0 / kCosBins, dp = 2 * M_PI / kPhiBins;
  const int split = 2;
  const double eps = 1e-7 / (split * split);  // absolute, per cell; ~0.05 counts per bin at n = 5e5
  for (int ic = 0; ic < kCosBins; ++ic)
    for (int ip = 0; ip < kPhiBins; ++ip) {
      double t0 = std::acos(std::min(1.0, -1 + (ic + 1) * dc)), t1 = std::acos(-1 + ic * dc);
      double sum = 0;
      for (int a = 0; a < split; ++a)
        for (int b = 0; b < split; ++b) {
          double x0 = t0 + a * (t1 - t0) / split, x1 = t0 + (a + 1) * (t1 - t0) / split;
          double y0 = ip * dp + b * dp / split, y1 = y0 + dp / split;
          sum += adaptive_simpson(f, x0, x1, y0, y1, simpson3x3(f, x0, x1, y0, y1), eps, 1e-4, 6);
        }
      expected[ic * kPhiBins + ip] = sum * double(n);
      r.pdf_integral += sum;
    }
  expected[expected.size() - 2] = r.delta_probability * double(n);
  expected.back() = std::max(0.0, 1.0 - r.pdf_integral - r.delta_probability) * double(n);

  // Pool the categories with the smallest expectations until the pool expects at least 5.
  std::vector<int> order(observed.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
  double pool_e = 0, pool_o = 0;
  int categories = 0;
  size_t k = 0;
  for (; k < order.size() && pool_e < 5.0; ++k) pool_e += expected[order[k]], pool_o += observed[order[k]];
  if (pool_e > 0) {
    r.statistic += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
    ++categories;
  }
  for (; k < order.size(); ++k) {
    double e = expected[order[k]], o = observed[order[k]];
    r.statistic += (o - e) * (o - e) / e;
    ++categories;
  }
  r.dof = categories - 1;
  r.p = chi_square_p_value(r.statistic, r.dof);
  return r;
}

}  // namespace pdrt::test
