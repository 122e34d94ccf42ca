#include "renderer/render/expected_splat_weight.h"

#include <algorithm>
#include <cmath>

namespace pdrt {
namespace {
constexpr int kCellsPerPixel = 64;
}

ExpectedSplatWeight::ExpectedSplatWeight(const Filter& filter, int image_width, int image_height)
    : width_(image_width), height_(image_height) {
  half_ = std::max(0, int(std::ceil(filter.radius() - 0.5f)));
  side_ = (2 * half_ + 1) * kCellsPerPixel;
  const double h = 1.0 / kCellsPerPixel, lo = -(half_ + 0.5);
  sat_.assign(std::size_t(side_ + 1) * (side_ + 1), 0.0);
  for (int j = 0; j < side_; ++j)
    for (int i = 0; i < side_; ++i) {
      const double f = filter.eval(float(lo + (i + 0.5) * h), float(lo + (j + 0.5) * h)) * h * h;
      sat_[std::size_t(j + 1) * (side_ + 1) + i + 1] = f + sat_[std::size_t(j) * (side_ + 1) + i + 1] +
                                                       sat_[std::size_t(j + 1) * (side_ + 1) + i] -
                                                       sat_[std::size_t(j) * (side_ + 1) + i];
    }
}

double ExpectedSplatWeight::at(int x, int y) const {
  // The grid's pixel column c (0 .. 2 half_) is image column x - half_ + c: those inside the image.
  const int i0 = std::clamp(half_ - x, 0, 2 * half_ + 1) * kCellsPerPixel;
  const int i1 = std::clamp(width_ - x + half_, 0, 2 * half_ + 1) * kCellsPerPixel;
  const int j0 = std::clamp(half_ - y, 0, 2 * half_ + 1) * kCellsPerPixel;
  const int j1 = std::clamp(height_ - y + half_, 0, 2 * half_ + 1) * kCellsPerPixel;
  if (i0 >= i1 || j0 >= j1) return 0.0;
  auto s = [&](int i, int j) { return sat_[std::size_t(j) * (side_ + 1) + i]; };
  return s(i1, j1) - s(i0, j1) - s(i1, j0) + s(i0, j0);
}

}  // namespace pdrt
