#include "renderer/compare/screen_maps.h"

#include "renderer/compare/heat_maps.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace {

// Decades of power below the largest that the spectrum images show at most.
constexpr double kSpectrumDecades = 6;

std::vector<float> log10_power(const std::vector<double>& p) {
  std::vector<float> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) out[i] = p[i] > 0 ? float(std::log10(p[i])) : -INFINITY;
  return out;
}

// The log10 power range of the runs' spectra at one spp: the largest value and, at most
// kSpectrumDecades below it, the 1st percentile.
std::array<double, 2> spectrum_range(const std::vector<std::vector<float>>& maps) {
  std::vector<float> all;
  for (const auto& m : maps)
    for (float v : m)
      if (std::isfinite(v)) all.push_back(v);
  if (all.empty()) return {-1, 0};
  std::sort(all.begin(), all.end());
  const double hi = all.back(), lo = std::max(double(all[std::size_t(0.01 * (all.size() - 1))]), hi - kSpectrumDecades);
  return {lo, hi > lo ? hi : lo + 1};
}

}  // namespace

std::vector<double> centred_spectrum(const std::vector<double>& power, int W, int H) {
  std::vector<double> out(power.size());
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) out[std::size_t((y + H / 2) % H) * W + (x + W / 2) % W] = power[std::size_t(y) * W + x];
  return out;
}

void write_screen_maps(const ReportContext& ctx, CompareResults& results) {
  for (UniformRun& r : results.runs) {
    const std::string stem = "errors/" + r.sampler + "-" + std::to_string(r.spp);
    r.flip_ldr_file = stem + "-flip-ldr.png", r.flip_hdr_file = stem + "-flip-hdr.png";
    ctx.write_png(r.flip_ldr_file, heat_rgb(r.screen.flip_ldr_map, 1.0f));
    ctx.write_png(r.flip_hdr_file, heat_rgb(r.screen.flip_hdr_map, 1.0f));
  }
  for (int n : ctx.o.spp) {
    std::vector<UniformRun*> at;
    std::vector<std::vector<float>> maps;
    for (UniformRun& r : results.runs)
      if (r.spp == n)
        at.push_back(&r), maps.push_back(log10_power(centred_spectrum(r.screen.spectrum, ctx.width, ctx.height)));
    const std::array<double, 2> range = spectrum_range(maps);
    results.spectrum_scale[n] = range;
    for (std::size_t i = 0; i < at.size(); ++i) {
      for (float& v : maps[i]) v = std::isfinite(v) ? float(v - range[0]) : 0.0f;
      at[i]->spectrum_file = "spectra/" + at[i]->sampler + "-" + std::to_string(n) + ".png";
      ctx.write_png(at[i]->spectrum_file, heat_rgb(maps[i], float(range[1] - range[0])));
    }
  }
}

}  // namespace pdrt
