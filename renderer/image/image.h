#pragma once
// A finished image as the renderer produces it and the image files hold it: linear RGB plus
// AOV planes, row-major from the top-left (render/film.h fills it; image_output.h writes and
// reads it).
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

}  // namespace pdrt
