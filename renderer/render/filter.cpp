#include "renderer/render/filter.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace {

// Mitchell–Netravali with B = C = 1/3, on x in [0, 2].
float mitchell_1d(float x) {
  const float B = 1.0f / 3, C = 1.0f / 3;
  x = std::abs(x);
  if (x >= 2) return 0;
  if (x > 1)
    return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6;
  return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6;
}

}  // namespace

Filter::Filter(const FilterDesc& d) : type_(d.type), radius_(d.radius) {
  // Cook's Gaussian: e^(-d^2) - e^(-w^2), d in pixels, w the radius (1.5 by default).
  gauss_tail_ = std::exp(-radius_ * radius_);
  max_ = eval(0, 0);
  for (int i = 0; i <= 256; ++i)
    for (int j = 0; j <= 256; ++j)
      min_ = std::min(min_, eval(radius_ * (i / 128.0f - 1), radius_ * (j / 128.0f - 1)));
}

float Filter::eval(float x, float y) const {
  if (std::abs(x) >= radius_ || std::abs(y) >= radius_) return 0;
  switch (type_) {
    case FilterType::Box:
      return 1;
    case FilterType::Tent:
      return (1 - std::abs(x) / radius_) * (1 - std::abs(y) / radius_);
    case FilterType::Gaussian: {
      float d2 = x * x + y * y;
      return d2 >= radius_ * radius_ ? 0.0f : std::exp(-d2) - gauss_tail_;
    }
    case FilterType::Mitchell:
      // The canonical filter spans 2 pixels; scale it to the requested radius.
      return mitchell_1d(2 * x / radius_) * mitchell_1d(2 * y / radius_);
  }
  return 0;
}

}  // namespace pdrt
