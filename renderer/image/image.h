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

// A width x height image with every plane sized (zeros). The planes are zeroed in parallel,
// one group per task: the first touch of an image's pages is the kernel's work, and on one
// thread it held up the end of every render (0.25 s of a 2.7 s 1080p render at 1 spp in the
// sandboxed 2-core VM, 2026-12-06).
Image sized_image(int width, int height);

}  // namespace pdrt
