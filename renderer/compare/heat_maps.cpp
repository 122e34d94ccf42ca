#include "renderer/compare/heat_maps.h"

#include "renderer/compare/image_metrics.h"

#include <algorithm>
#include <map>

namespace pdrt {

Vec3 heat(float t) {
  t = std::clamp(t, 0.0f, 1.0f) * 4;
  int i = std::min(int(t), 3);
  const auto& a = kHeatStops[i];
  const auto& b = kHeatStops[i + 1];
  return lerp(t - i, Vec3(a[0], a[1], a[2]), Vec3(b[0], b[1], b[2]));
}

std::vector<float> heat_rgb(const std::vector<float>& values, float scale) {
  std::vector<float> rgb(3 * values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    Vec3 c = heat(values[i] / scale);
    rgb[3 * i] = c.x, rgb[3 * i + 1] = c.y, rgb[3 * i + 2] = c.z;
  }
  return rgb;
}

float heat_scale(std::vector<float> values) {
  if (values.empty()) return 1e-6f;
  const auto at = values.begin() + std::ptrdiff_t(0.99 * double(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return std::max(*at, 1e-6f);
}

void write_heat_maps(const ReportContext& ctx, CompareResults& results) {
  for (int n : ctx.o.spp) {
    std::vector<float> all;
    std::map<std::string, std::vector<float>> maps;
    for (const UniformRun& r : results.runs)
      if (r.spp == n) {
        maps[r.sampler] = error_map(r.image, results.reference.image);
        all.insert(all.end(), maps[r.sampler].begin(), maps[r.sampler].end());
      }
    const float scale = heat_scale(std::move(all));
    results.heat_scale[n] = scale;
    for (const UniformRun& r : results.runs)
      if (r.spp == n) ctx.write_png(r.error_file, heat_rgb(maps[r.sampler], scale));
  }
}

}  // namespace pdrt
