#include "renderer/image/image.h"

#include <tbb/parallel_invoke.h>

namespace pdrt {

Image sized_image(int width, int height) {
  Image img;
  img.width = width, img.height = height;
  const std::size_t n = std::size_t(width) * std::size_t(height);
  tbb::parallel_invoke([&] { img.rgb.resize(3 * n); }, [&] { img.albedo.resize(3 * n); },
                       [&] { img.normal.resize(3 * n); },
                       [&] { img.samples.resize(n), img.variance.resize(n), img.depth.resize(n); });
  return img;
}

}  // namespace pdrt
