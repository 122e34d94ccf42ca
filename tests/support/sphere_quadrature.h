#pragma once
// Brute-force integrals over the sphere of directions for the BSDF tests: a midpoint rule in
// (theta, phi), fine enough for lobes of roughness >= 0.25 to ~1e-4.
#include "renderer/render/bsdf.h"

#include <cmath>

namespace pdrt::test {

// Integral of f(w) dw over the whole sphere (nt x np cells).
template <class F>
double integrate_sphere(F f, int nt = 2048, int np = 1024) {
  double sum = 0;
  for (int i = 0; i < nt; ++i) {
    double theta = M_PI * (i + 0.5) / nt, st = std::sin(theta), ct = std::cos(theta);
    for (int j = 0; j < np; ++j) {
      double phi = 2 * M_PI * (j + 0.5) / np;
      sum += f(Vec3{float(st * std::cos(phi)), float(st * std::sin(phi)), float(ct)}) * st;
    }
  }
  return sum * (M_PI / nt) * (2 * M_PI / np);
}

// Energy albedo of channel k seen from wo: int f(wo, wi) |cos wi| dwi, with transmission's
// 1 / eta^2 radiance scaling undone (eta = ior from outside, 1 / ior from inside).
inline double energy_albedo(const Bsdf& bsdf, const Vec3& wo, float ior = 1, int k = 0, int nt = 2048, int np = 1024) {
  double eta = wo.z > 0 ? ior : 1.0 / ior;
  return integrate_sphere(
      [&](const Vec3& wi) {
        double v = bsdf.eval(wo, wi)[k] * std::abs(wi.z);
        return (wi.z > 0) != (wo.z > 0) ? v * eta * eta : v;
      },
      nt, np);
}

}  // namespace pdrt::test
