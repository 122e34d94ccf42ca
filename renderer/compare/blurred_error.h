#pragma once
// The error the eye integrates: the error image (render - reference) blurred by a Gaussian of
// sigma = 1 and 2 pixels before its RMSE is taken. Blurring is linear, so the blurred error is
// blur(render) - blur(reference), and a comparison blurs every image once and hands them to the
// ordinary seed statistics (seed_statistics.h; the reference's noise is that of its blurred
// halves).
#include "renderer/render/film.h"

#include <array>

namespace pdrt {

// The blur widths of the report, in pixels.
inline constexpr std::array<double, 2> kBlurSigmas = {1.0, 2.0};

// `im` (its rgb only) convolved with a Gaussian of standard deviation `sigma` pixels, sampled at
// integer offsets and cut at radius ceil(4 sigma), applied along x and then y. Boundary: the
// kernel is renormalised over the pixels inside the image (normalised convolution), so each
// output is a weighted mean of image pixels only and a constant image stays that constant;
// nothing is invented beyond the edge (no clamped or mirrored copies). sigma <= 0 returns `im`.
Image gaussian_blur(const Image& im, double sigma);

// RMSE over pixels and channels of the error test - reference blurred by sigma pixels.
double blurred_rmse(const Image& test, const Image& reference, double sigma);

// Per pixel, the magnitude of the blurred error's luminance, |Y(blur(test) - blur(reference))|
// (linear), for the blurred-error heat maps; `blurred_reference` is gaussian_blur(reference, sigma).
std::vector<float> blurred_error_map(const Image& test, const Image& blurred_reference, double sigma);

}  // namespace pdrt
