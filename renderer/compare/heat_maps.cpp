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

std::map<int, float> write_heat_pngs(const ReportContext& ctx, const std::vector<UniformRun>& runs,
                                     const std::vector<std::vector<float>>& maps,
                                     const std::function<std::string(const UniformRun&)>& file_of) {
  std::map<int, std::vector<float>> by_spp;
  for (std::size_t i = 0; i < runs.size(); ++i)
    by_spp[runs[i].spp].insert(by_spp[runs[i].spp].end(), maps[i].begin(), maps[i].end());
  std::map<int, float> scales;
  for (auto& [n, values] : by_spp) scales[n] = heat_scale(std::move(values));
  for (std::size_t i = 0; i < runs.size(); ++i) ctx.write_png(file_of(runs[i]), heat_rgb(maps[i], scales[runs[i].spp]));
  return scales;
}

void write_heat_maps(const ReportContext& ctx, CompareResults& results) {
  std::vector<std::vector<float>> maps;
  for (const UniformRun& r : results.runs) maps.push_back(error_map(r.image, results.reference.image));
  results.heat_scale = write_heat_pngs(ctx, results.runs, maps, [](const UniformRun& r) { return r.error_file; });
}

}  // namespace pdrt
