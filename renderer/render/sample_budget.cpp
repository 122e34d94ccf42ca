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

std::string format_sample_cost(double total, double seconds_per_sample, bool measured, double fixed_seconds) {
  const double seconds = total * seconds_per_sample + fixed_seconds, hours = seconds / 3600;
  char buf[160];
  if (hours >= 48)
    std::snprintf(buf, sizeof buf, "%.3g samples (about %.0f days", total, hours / 24);
  else if (hours >= 1)
    std::snprintf(buf, sizeof buf, "%.3g samples (about %.1f hours", total, hours);
  else if (seconds >= 60)
    std::snprintf(buf, sizeof buf, "%.3g samples (about %.0f min", total, seconds / 60);
  else
    std::snprintf(buf, sizeof buf, "%.3g samples (about %.2g s", total, seconds);
  const double ns = seconds_per_sample * 1e9;
  char rate[96];
  std::snprintf(rate, sizeof rate, ns >= 10 ? " at %.0f ns per sample" : " at %.2g ns per sample", ns);
  return std::string(buf) + rate + (measured ? ", measured on this scene)" : ")");
}

void check_sample_budget(double total, double seconds_per_sample, bool measured, const std::string& what, bool allow) {
  if (allow || total * seconds_per_sample <= kMaxEstimatedSeconds) return;
  throw UsageError(what + " = " + format_sample_cost(total, seconds_per_sample, measured) +
                   ", more than the limit of 46 min; lower the spp or the resolution, or pass --allow-long-render");
}

}  // namespace pdrt
