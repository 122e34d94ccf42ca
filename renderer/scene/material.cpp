#include "renderer/scene/material.h"

#include <algorithm>
#include <cmath>

namespace pdrt {
namespace {

// Complex refractive index n + ik of bulk metals at 650 nm (R), 550 nm (G) and 450 nm (B), the
// wavelengths one RGB channel stands for here (a point sample, not a spectral integral against
// the sRGB matching functions). Each value is the linear interpolation in wavelength between the
// two published entries that bracket it, as tabulated by the refractiveindex.info database
// (M. N. Polyanskiy, Sci. Data 11, 94, 2024):
//   Au, Ag, Cu  P. B. Johnson and R. W. Christy, Phys. Rev. B 6, 4370 (1972), entries at 0.4305,
//               0.4509, 0.5209, 0.5486, 0.6168 and 0.6595 um.
//   Al          A. D. Rakic, Appl. Opt. 34, 4755 (1995), entries at 0.4428, 0.4769, 0.5166,
//               0.5636, 0.6199 and 0.6523 um.
// tests/renderer/render/test_bsdf.cpp checks the reflectance against those entries.
constexpr NamedMetal kMetals[] = {
    {"Ag", {0.0522f, 0.0596f, 0.0400f}, {4.4094f, 3.5974f, 2.6484f}},
    {"Al", {1.5580f, 1.0152f, 0.6332f}, {7.7124f, 6.6273f, 5.4544f}},
    {"Au", {0.1556f, 0.4241f, 1.3831f}, {3.6024f, 2.4721f, 1.9155f}},
    {"Cu", {0.2378f, 1.0066f, 1.2404f}, {3.6264f, 2.5823f, 2.3929f}},
};

}  // namespace

const NamedMetal* find_named_metal(const std::string& name) {
  for (const NamedMetal& m : kMetals)
    if (name == m.name) return &m;
  return nullptr;
}

void conductor_from_reflectance(const Vec3& r, Material* m) {
  m->eta = Vec3(1.0f);
  for (int c = 0; c < 3; ++c) {
    const float rc = r[c] >= 0 ? std::min(r[c], 0.9999f) : 0.0f;  // NaN -> 0
    m->k[c] = 2 * std::sqrt(rc) / std::sqrt(1 - rc);
  }
}

std::string named_metal_list() {
  std::string s;
  for (const NamedMetal& m : kMetals) s += std::string(s.empty() ? "" : ", ") + "\"" + m.name + "\"";
  return s;
}

}  // namespace pdrt
