#include "renderer/render/sample_budget.h"

#include "sampling/core/errors.h"

#include <cstdio>

namespace pdrt {

double scene_sample_count(const SceneDesc& s) {
  const int spp = s.sampler.adaptive.enabled ? s.sampler.adaptive.max_spp : s.sampler.spp;
  return double(s.film.width) * double(s.film.height) * double(spp);
}

std::string describe_sample_count(const SceneDesc& s) {
  std::string d = std::to_string(s.film.width) + "x" + std::to_string(s.film.height) + " pixels x ";
  if (s.sampler.adaptive.enabled) return d + "max_spp " + std::to_string(s.sampler.adaptive.max_spp) + " (adaptive)";
  return d + std::to_string(s.sampler.spp) + " spp";
}

std::string format_sample_cost(double total) {
  const double hours = total * kSecondsPerSample / 3600;
  char buf[96];
  if (hours >= 48)
    std::snprintf(buf, sizeof buf, "%.3g samples (about %.0f days", total, hours / 24);
  else if (hours >= 1)
    std::snprintf(buf, sizeof buf, "%.3g samples (about %.1f hours", total, hours);
  else
    std::snprintf(buf, sizeof buf, "%.3g samples (about %.0f s", total, hours * 3600);
  return std::string(buf) + " at 277 ns per sample)";
}

void check_sample_budget(double total, const std::string& what, bool allow) {
  if (allow || total <= kMaxTotalSamples) return;
  throw UsageError(
      what + " = " + format_sample_cost(total) +
      ", more than the limit of 1e10 samples; lower the spp or the resolution, or pass --allow-long-render");
}

}  // namespace pdrt
