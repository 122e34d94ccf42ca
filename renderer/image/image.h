#pragma once
// A finished image as the renderer produces it and the image files hold it: linear RGB plus
// AOV planes, row-major from the top-left (render/film.h fills it; image_output.h writes and
// reads it).
#include <cstddef>
#include <vector>

namespace pdrt {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;       // 3 per pixel
  std::vector<float> samples;   // 1 per pixel
  std::vector<float> variance;  // 1 per pixel
  std::vector<float> albedo;    // 3 per pixel
  std::vector<float> normal;    // 3 per pixel
  std::vector<float> depth;     // 1 per pixel (infinity where nothing was hit)
};

// A width x height image with every plane sized (zeros).
inline Image sized_image(int width, int height) {
  Image img;
  img.width = width, img.height = height;
  const std::size_t n = std::size_t(width) * std::size_t(height);
  img.rgb.resize(3 * n), img.albedo.resize(3 * n), img.normal.resize(3 * n);
  img.samples.resize(n), img.variance.resize(n), img.depth.resize(n);
  return img;
}

}  // namespace pdrt
