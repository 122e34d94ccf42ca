#pragma once
// Spectral parameters of pbrt-v4 files turned into pdrt's linear-sRGB triples
// (docs/pbrt-import.md, "Spectra"). The CIE 1931 matching functions are Wyman, Sloan and
// Shirley's multi-lobe Gaussian fit (JCGT 2(2), 2013), within a few percent of the tables.
#include "renderer/scene/vec3.h"

#include <optional>
#include <string>
#include <vector>

namespace pdrt {

// CIE 1931 2° matching functions at wavelength `nm` (Wyman et al. 2013, the multi-lobe fit).
Vec3 cie_xyz_bar(double nm);
Vec3 xyz_to_linear_srgb(const Vec3& xyz);

// A piecewise-linear spectrum given as (nm, value) pairs, zero outside its range:
//   emission: scaled to luminance Y = 1, as pbrt-v4's lights divide by the spectrum's
//             photometric value (then `scale` multiplies it)
//   reflectance: its colour under an equal-energy white, normalised so a constant spectrum v
//             maps to (v, v, v)
Vec3 sampled_spectrum_to_rgb(const std::vector<double>& nm_value_pairs, bool emission);

// Planck's law at `kelvin`, normalised to luminance Y = 1 (pbrt-v4 normalises blackbody
// emitters the same way).
Vec3 blackbody_rgb(double kelvin);

// pbrt-v4's named illuminant spectra ("stdillum-A", "stdillum-D50", "stdillum-D65",
// "stdillum-F1" ... "stdillum-F12", "illum-acesD60") at luminance Y = 1, from their CIE 1931
// chromaticities (CIE 15:2004 tables; A is Planck's law at 2856 K); nullopt for other names.
std::optional<Vec3> named_illuminant_rgb(const std::string& name);

}  // namespace pdrt
