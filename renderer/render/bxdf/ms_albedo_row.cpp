#include "renderer/render/bxdf/ms_albedo_row.h"

#include <algorithm>

namespace pdrt {

float MsAlbedoRow::at(float mu, int side) const {
  float g = std::clamp(mu, 0.0f, 1.0f) * float(nodes - 1);
  int i = std::min(int(g), nodes - 2);
  const float* row = e[side];
  return std::min(1.0f, row[i] + (row[i + 1] - row[i]) * (g - float(i)));
}

}  // namespace pdrt
