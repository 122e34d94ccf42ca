#include "app/partial_summary.h"

#include <algorithm>
#include <cstdint>

namespace pdrt::cli {

namespace {
std::string spp_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}
}  // namespace

std::string describe_partial_coverage(const std::vector<float>& samples, int target_spp) {
  int64_t empty = 0, full = 0;
  float lo = 0, hi = 0;
  bool any = false;
  for (float s : samples) {
    if (s <= 0) {
      ++empty;
      continue;
    }
    lo = any ? std::min(lo, s) : s;
    hi = any ? std::max(hi, s) : s;
    any = true;
    full += target_spp > 0 && s >= float(target_spp);
  }
  const int64_t total = int64_t(samples.size()), rendered = total - empty;
  std::string text = std::to_string(rendered) + " of " + std::to_string(total) + " pixels rendered";
  if (rendered > 0) {
    text += " at " + spp_text(lo) + (hi > lo ? "–" + spp_text(hi) : "") + " spp";
    if (target_spp > 0) {
      text += " (of " + std::to_string(target_spp) + ")";
      if (full > 0 && full < rendered) text += ", " + std::to_string(full) + " of them complete";
    }
  }
  if (empty > 0) text += ", " + std::to_string(empty) + " without samples";
  return text;
}

}  // namespace pdrt::cli
