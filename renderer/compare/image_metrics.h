#pragma once
// Error of a rendered image against a reference: RMSE, relative MSE, error maps, fireflies
// and specks (the error's spectrum is error_spectrum.h's).
#include "renderer/render/film.h"

#include <vector>

namespace pdrt {

// Root mean squared error over all pixels and the three channels.
double rmse(const Image& test, const Image& reference);

// Relative MSE (Rousselle et al. 2011): mean of (t - r)^2 / (r^2 + eps), eps = 0.01.
double relative_mse(const Image& test, const Image& reference, double eps = 0.01);

// Per-pixel absolute luminance error, for heat maps.
std::vector<float> error_map(const Image& test, const Image& reference);

// Fireflies: pixels whose luminance is more than `ratio` times the median luminance of their
// 3x3 neighbourhood (the pixel itself included; the image's edge is extended by its border
// pixels) and above that median by more than `floor` (linear luminance; 0 = the ratio alone,
// under which any lit pixel whose neighbourhood median is black counts). `firefly_mask` marks
// them (1) in a width * height mask.
std::vector<unsigned char> firefly_mask(const Image& image, double ratio = 10, double floor = 0);

struct FireflyCount {
  long long test = 0;       // fireflies of the test image
  long long reference = 0;  // fireflies of the reference
  long long extra = 0;      // of the test image where the reference has none: the count that matters
};
FireflyCount count_fireflies(const Image& test, const Image& reference, double ratio = 10, double floor = 0);

// Specks: pixels whose luminance is more than `ratio` times the reference's at the same pixel
// and above it by more than `floor` (linear luminance, as the PNG shows it). The visible white
// dots of caustic paths sit at 2-4x their neighbours, which the 3x3 median test misses once the
// reconstruction filter has spread them; the converged reference sees them.
std::vector<unsigned char> speck_mask(const Image& test, const Image& reference, double ratio = 3, double floor = 0.05);
long long count_specks(const Image& test, const Image& reference, double ratio = 3, double floor = 0.05);

}  // namespace pdrt
