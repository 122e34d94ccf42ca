#include "renderer/scene/pbrt/pbrt_spectrum.h"

#include <cmath>

namespace pdrt {

namespace {

// Piecewise Gaussian: sigma1 left of the mean, sigma2 right of it (Wyman et al. 2013, eq. 1).
double g(double x, double mu, double s1, double s2) {
  const double t = (x - mu) / (x < mu ? s1 : s2);
  return std::exp(-0.5 * t * t);
}

constexpr double kLo = 360, kHi = 830, kStep = 1;

template <class F>
Vec3 integrate_xyz(F&& value) {
  double x = 0, y = 0, z = 0;
  for (double nm = kLo; nm <= kHi; nm += kStep) {
    const double v = value(nm);
    const Vec3 c = cie_xyz_bar(nm);
    x += v * c.x, y += v * c.y, z += v * c.z;
  }
  return {float(x), float(y), float(z)};
}

double piecewise_linear(const std::vector<double>& p, double nm) {
  const size_t n = p.size() / 2;
  if (n == 0 || nm < p[0] || nm > p[2 * (n - 1)]) return 0;
  for (size_t i = 0; i + 1 < n; ++i) {
    const double a = p[2 * i], b = p[2 * i + 2];
    if (nm >= a && nm <= b)
      return b > a ? p[2 * i + 1] + (nm - a) / (b - a) * (p[2 * i + 3] - p[2 * i + 1]) : p[2 * i + 1];
  }
  return n == 1 ? p[1] : 0;
}

}  // namespace

Vec3 cie_xyz_bar(double nm) {
  const double x =
      1.056 * g(nm, 599.8, 37.9, 31.0) + 0.362 * g(nm, 442.0, 16.0, 26.7) - 0.065 * g(nm, 501.1, 20.4, 26.2);
  const double y = 0.821 * g(nm, 568.8, 46.9, 40.5) + 0.286 * g(nm, 530.9, 16.3, 31.1);
  const double z = 1.217 * g(nm, 437.0, 11.8, 36.0) + 0.681 * g(nm, 459.0, 26.0, 13.8);
  return {float(x), float(y), float(z)};
}

Vec3 xyz_to_linear_srgb(const Vec3& c) {
  // IEC 61966-2-1 (D65 white).
  return {3.2404542f * c.x - 1.5371385f * c.y - 0.4985314f * c.z,
          -0.9692660f * c.x + 1.8760108f * c.y + 0.0415560f * c.z,
          0.0556434f * c.x - 0.2040259f * c.y + 1.0572252f * c.z};
}

Vec3 sampled_spectrum_to_rgb(const std::vector<double>& p, bool emission) {
  const Vec3 xyz = integrate_xyz([&](double nm) { return piecewise_linear(p, nm); });
  if (emission) {
    if (!(xyz.y > 0)) return Vec3(0.0f);
    return xyz_to_linear_srgb(xyz / xyz.y);
  }
  const Vec3 white = xyz_to_linear_srgb(integrate_xyz([](double) { return 1.0; }));
  const Vec3 rgb = xyz_to_linear_srgb(xyz);
  return {rgb.x / white.x, rgb.y / white.y, rgb.z / white.z};
}

Vec3 blackbody_rgb(double kelvin) {
  const double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
  const Vec3 xyz = integrate_xyz([&](double nm) {
    const double l = nm * 1e-9;
    return (2 * h * c * c) / (std::pow(l, 5) * (std::exp((h * c) / (l * kb * kelvin)) - 1));
  });
  if (!(xyz.y > 0)) return Vec3(0.0f);
  return xyz_to_linear_srgb(xyz / xyz.y);
}

std::optional<Vec3> named_illuminant_rgb(const std::string& name) {
  if (name == "stdillum-A") return blackbody_rgb(2856);
  struct Chromaticity {
    const char* name;
    double x, y;
  };
  // CIE 15:2004, Table T.3 (D series) and T.8 (F series); ACES D60 from SMPTE ST 2065-1.
  static const Chromaticity kTable[] = {
      {"stdillum-D50", 0.34567, 0.35850}, {"stdillum-D65", 0.31271, 0.32902}, {"illum-acesD60", 0.32168, 0.33767},
      {"stdillum-F1", 0.31310, 0.33727},  {"stdillum-F2", 0.37208, 0.37529},  {"stdillum-F3", 0.40910, 0.39430},
      {"stdillum-F4", 0.44018, 0.40329},  {"stdillum-F5", 0.31379, 0.34531},  {"stdillum-F6", 0.37790, 0.38835},
      {"stdillum-F7", 0.31292, 0.32933},  {"stdillum-F8", 0.34588, 0.35875},  {"stdillum-F9", 0.37417, 0.37281},
      {"stdillum-F10", 0.34609, 0.35986}, {"stdillum-F11", 0.38052, 0.37713}, {"stdillum-F12", 0.43695, 0.40441}};
  for (const Chromaticity& c : kTable)
    if (name == c.name) return xyz_to_linear_srgb(Vec3(float(c.x / c.y), 1.0f, float((1 - c.x - c.y) / c.y)));
  return std::nullopt;
}

}  // namespace pdrt
