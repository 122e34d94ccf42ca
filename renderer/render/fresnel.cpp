#include "renderer/render/fresnel.h"

#include <complex>

namespace pdrt {

// Snell: sin_t = sin_i / eta; the result is -w / eta + (cos_i / eta - cos_t) n.
bool refract(const Vec3& w, const Vec3& n, float eta, Vec3* wt) {
  float cos_i = dot(w, n);
  float sin2_t = std::max(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0f) return false;
  float cos_t = std::sqrt(1.0f - sin2_t);
  *wt = -w / eta + n * (cos_i / eta - cos_t);
  return true;
}

double fresnel_dielectric(double cos_i, double eta) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1.0) return 1.0;
  double cos_t = std::sqrt(1.0 - sin2_t);
  // Amplitude coefficients for s and p polarisation (Born & Wolf §1.5.2), averaged in power.
  double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5f * (rs * rs + rp * rp);
}

double fresnel_dielectric_average(double eta) {
  // Midpoint rule in mu^2 (2 mu dmu = d(mu^2)): smooth but for the kink at the critical angle.
  const int n = 4096;
  double s = 0;
  for (int i = 0; i < n; ++i) s += fresnel_dielectric(std::sqrt((i + 0.5) / n), eta);
  return s / n;
}

double fresnel_dielectric_average_closed(double eta) {
  double n = std::max(1.0, eta);
  // Near n = 1 the terms below cancel (1e-8 lost at n - 1 = 3e-5), where the first order,
  // (n - 1) / 3, is as close.
  if (n - 1 < 3e-5) return (n - 1) / 3;
  // The integral of the unpolarised Fresnel reflectance against 2 mu dmu done analytically
  // (rational terms and logarithms in n: the standard closed form of a dielectric boundary's
  // diffuse reflectance). Checked against fresnel_dielectric_average in test_coated_diffuse.cpp.
  double n2 = n * n, n4 = n2 * n2;
  return 0.5 + (n - 1) * (3 * n + 1) / (6 * (n + 1) * (n + 1)) +
         n2 * (n2 - 1) * (n2 - 1) / ((n2 + 1) * (n2 + 1) * (n2 + 1)) * std::log((n - 1) / (n + 1)) -
         2 * n2 * n * (n2 + 2 * n - 1) / ((n2 + 1) * (n4 - 1)) +
         8 * n4 * (n4 + 1) / ((n2 + 1) * (n4 - 1) * (n4 - 1)) * std::log(n);
}

double fresnel_conductor(double cos_i, double eta, double k) {
  using C = std::complex<double>;
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  const C n(eta, k);
  const C sin2_t = (1.0 - cos_i * cos_i) / (n * n);
  const C cos_t = std::sqrt(1.0 - sin2_t);  // principal root: Re >= 0, the wave decays inside
  const C rs = (cos_i - n * cos_t) / (cos_i + n * cos_t);
  const C rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
  return std::min(1.0, 0.5 * (std::norm(rs) + std::norm(rp)));
}

Vec3 fresnel_conductor(float cos_i, const Vec3& eta, const Vec3& k) {
  return {float(fresnel_conductor(cos_i, eta.x, k.x)), float(fresnel_conductor(cos_i, eta.y, k.y)),
          float(fresnel_conductor(cos_i, eta.z, k.z))};
}

Vec3 fresnel_conductor_average(const Vec3& eta, const Vec3& k) {
  // Midpoint rule in mu^2, as fresnel_dielectric_average (smooth: no critical angle for k > 0).
  const int n = 1024;
  double s[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    double mu = std::sqrt((i + 0.5) / n);
    for (int c = 0; c < 3; ++c) s[c] += fresnel_conductor(mu, eta[c], k[c]);
  }
  return {float(s[0] / n), float(s[1] / n), float(s[2] / n)};
}

double conductor_r0(double eta, double k) { return ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k); }

Vec3 fresnel_schlick(const Vec3& f0, float cos_i) {
  float m = std::clamp(1.0f - cos_i, 0.0f, 1.0f);
  float m5 = (m * m) * (m * m) * m;
  return f0 + (Vec3(1.0f) - f0) * m5;
}

}  // namespace pdrt
