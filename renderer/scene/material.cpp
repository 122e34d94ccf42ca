#include "renderer/scene/material.h"

namespace pdrt {
namespace {

// Complex refractive index n + ik of bulk metals sampled at 650 nm (R), 550 nm (G) and 450 nm
// (B), the wavelengths one RGB channel stands for here (a point sample, not a spectral
// integral against the sRGB matching functions). Sources, as tabulated by the refractiveindex.info
// database (M. N. Polyanskiy, Sci. Data 11, 94, 2024):
//   Au  D. I. Yakubovsky et al., Opt. Express 25, 25574 (2017), 53 nm e-beam film: the table's
//       own entries at 0.65 / 0.55 / 0.45 um.
//   Ag  P. B. Johnson and R. W. Christy, Phys. Rev. B 6, 4370 (1972): entries nearest 650 /
//       550 / 450 nm (0.6526 / 0.5486 / 0.4509 um).
//   Cu  Johnson and Christy 1972, same entries.
//   Al  A. D. Rakic, Appl. Opt. 34, 4755 (1995), at 650 / 550 / 450 nm.
// The Ag, Cu and Al digits are rounded to 2-3 significant figures.
constexpr NamedMetal kMetals[] = {
    {"Ag", {0.051f, 0.059f, 0.040f}, {4.483f, 3.586f, 2.657f}},
    {"Al", {1.49f, 0.96f, 0.62f}, {7.82f, 6.69f, 5.47f}},
    {"Au", {0.177031f, 0.377195f, 1.515997f}, {3.772157f, 2.612970f, 1.961270f}},
    {"Cu", {0.214f, 1.02f, 1.24f}, {3.67f, 2.58f, 2.40f}},
};

}  // namespace

const NamedMetal* find_named_metal(const std::string& name) {
  for (const NamedMetal& m : kMetals)
    if (name == m.name) return &m;
  return nullptr;
}

std::string named_metal_list() {
  std::string s;
  for (const NamedMetal& m : kMetals) s += std::string(s.empty() ? "" : ", ") + "\"" + m.name + "\"";
  return s;
}

}  // namespace pdrt
