#pragma once
// ꟻLIP, a perceptual difference of two images as they are flipped back and forth on a monitor:
// LDR-FLIP (P. Andersson, J. Nilsson, T. Akenine-Möller, M. Oskarsson, K. Åström, M. D.
// Fairchild, "FLIP: A Difference Evaluator for Alternating Images", HPG 2020) and HDR-FLIP
// (P. Andersson, J. Nilsson, P. Shirley, T. Akenine-Möller, "Visualizing Errors in Rendered High
// Dynamic Range Images", Eurographics 2021 short papers). Written from the papers' formulas.
//
// LDR-FLIP, per pixel, in [0, 1]:
//  colour: linear RGB in [0, 1] -> XYZ (sRGB primaries, D65) -> YyCxCz opponent space; each
//    channel filtered by its contrast sensitivity function, a sum of Gaussians in visual degrees
//    a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 x^2 / b2) with
//    (a1, b1, a2, b2) = (1, 0.0047, 0, 1e-5) achromatic, (1, 0.0053, 0, 1e-5) red-green and
//    (34.1, 0.04, 13.5, 0.025) blue-yellow, radius ceil(3 sqrt(0.04 / (2 pi^2)) ppd) pixels and
//    normalised to sum 1; back to linear RGB clamped to [0, 1]; CIE L*a*b*, Hunt-adjusted
//    (a, b scaled by 0.01 L); HyAB distance |dL| + sqrt(da^2 + db^2) raised to q_c = 0.7 and
//    remapped with c_max = HyAB(green, blue)^0.7: below p_c c_max linearly to [0, p_t], above
//    linearly to [p_t, 1], p_c = 0.4, p_t = 0.95. That is dE_c.
//  features: on the achromatic channel (relative luminance Y / Y_white of the unfiltered input),
//    the first (edges) and second (points) derivatives of a Gaussian of sigma = 0.5 w ppd pixels,
//    w = 0.082 degrees, radius ceil(3 sigma), along x and y, each kernel's positive weights
//    normalised to sum 1 and its negative weights to -1; dE_f = (max(| |edge_r| - |edge_t| |,
//    | |point_r| - |point_t| |) / sqrt(2))^q_f, q_f = 0.5.
//  FLIP = dE_c^(1 - dE_f).
// Filters replicate the border pixels (as the papers' code does). Everything in it is a
// function of |reference - test| terms, so LDR-FLIP is symmetric in its two images; HDR-FLIP is
// not (its exposures come from the reference alone).
//
// HDR-FLIP: linear HDR images are tone mapped by the papers' fit of ACES,
// T(x) = (k0 x^2 + k1 x) / (k3 x^2 + k4 x + k5) clamped to [0, 1], k0 = 0.6^2 2.51, k1 = 0.6 0.03,
// k3 = 0.6^2 2.43, k4 = 0.6 0.59, k5 = 0.14, at exposures 2^c for c from c_start =
// log2(x_max / Y_max) to c_stop = log2(x_max / median Y) (Y the reference's luminance,
// T(x_max) = 0.85) in max(2, ceil(c_stop - c_start)) even steps; HDR-FLIP is the per-pixel
// maximum of LDR-FLIP over them.
#include "renderer/render/film.h"

#include <vector>

namespace pdrt {

// Pixels per degree of visual angle: the papers' default observer, a 0.7 m wide 3840-pixel
// monitor seen from 0.7 m: 3840 / 0.7 * 0.7 * pi / 180 = 67.02.
inline constexpr double kFlipPixelsPerDegree = 3840.0 * 3.14159265358979323846 / 180.0;

// An image as LDR-FLIP's two pipelines see it, prepared once and compared with many.
struct FlipView {
  int width = 0, height = 0;
  std::vector<float> L, a, b;      // CSF-filtered, Hunt-adjusted L*a*b*
  std::vector<float> edge, point;  // magnitudes of the edge and point detectors
};

// The view of linear RGB `rgb` (3 per pixel, width x height), each value clamped to [0, 1]
// first (NaN to 0): LDR-FLIP's input is a display image.
FlipView flip_view(const std::vector<float>& rgb, int width, int height, double ppd = kFlipPixelsPerDegree);

// Per-pixel LDR-FLIP between two views of one size and pixels per degree.
std::vector<float> flip_error(const FlipView& reference, const FlipView& test);

// LDR-FLIP of two linear images clamped to [0, 1] (what the report's PNGs show).
std::vector<float> ldr_flip(const Image& reference, const Image& test, double ppd = kFlipPixelsPerDegree);

// HDR-FLIP's exposure range, from the reference's finite luminances. When their median is 0
// (more than half the reference black) c_stop takes the median of the positive luminances
// instead (the papers' formula would give infinity); a black reference gives c_start = c_stop = 0.
struct FlipExposures {
  double start = 0, stop = 0;
  int count = 2;
  double at(int i) const { return start + i * (stop - start) / (count - 1); }
};
FlipExposures hdr_flip_exposures(const Image& reference);

// `im` exposed by 2^exposure and tone mapped by the ACES fit: linear RGB in [0, 1].
std::vector<float> flip_tone_map(const Image& im, double exposure);

// The reference of HDR-FLIP prepared at each of its exposures.
struct HdrFlipReference {
  FlipExposures exposures;
  double ppd = kFlipPixelsPerDegree;
  std::vector<FlipView> views;
};
HdrFlipReference hdr_flip_reference(const Image& reference, double ppd = kFlipPixelsPerDegree);

// Per-pixel HDR-FLIP of `test` against a prepared reference, and against a plain one.
std::vector<float> hdr_flip(const HdrFlipReference& reference, const Image& test);
std::vector<float> hdr_flip(const Image& reference, const Image& test, double ppd = kFlipPixelsPerDegree);

// The mean of a FLIP map (the papers' pooled value).
double mean_flip(const std::vector<float>& map);

}  // namespace pdrt
