#include "adaptive_metric.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pdrt {

namespace {

// Floors that keep a black pixel (mean 0) from demanding an error of 0.
constexpr double kRelativeFloor = 1e-3;
constexpr double kImageMeanFloor = 1e-4;

}  // namespace

double default_threshold(const std::string& metric) {
  if (metric == "error-per-sample") return 1.0 / 16;
  if (metric == "relative-error") return 0.01;
  if (metric == "contrast") return 0.4;
  throw std::invalid_argument("unknown adaptive metric \"" + metric + "\"");
}

double effective_threshold(const AdaptiveDesc& ad) {
  return ad.threshold > 0 ? double(ad.threshold) : default_threshold(ad.metric);
}

AdaptiveMetric::AdaptiveMetric(const AdaptiveDesc& ad)
    : halves_(ad.variance == "halves"), threshold_(effective_threshold(ad)) {
  kind_ = ad.metric == "contrast"         ? Kind::Contrast
          : ad.metric == "relative-error" ? Kind::RelativeError
                                          : Kind::ErrorPerSample;
  if (ad.variance != "samples" && !halves_) throw std::invalid_argument("unknown adaptive variance \"" + ad.variance + "\"");
}

bool AdaptiveMetric::converged(const PixelAccum& p) const {
  if (p.samples < 2 || p.w == 0) return false;  // no spread to judge yet
  if (kind_ == Kind::Contrast) {
    // Mitchell (1987): per-channel thresholds t, 0.75 t, 1.5 t (0.4/0.3/0.6 for t = 0.4).
    const double scale[3] = {1.0, 0.75, 1.5};
    for (int k = 0; k < 3; ++k)
      if (p.contrast(k) > threshold_ * scale[k]) return false;
    return true;
  }
  const double standard_error = std::sqrt(halves_ ? p.half_variance_of_mean() : p.variance_of_mean());
  const double mean = std::abs(p.mean_luminance());
  if (kind_ == Kind::RelativeError) return standard_error <= threshold_ * std::max(mean, kRelativeFloor);
  // error-per-sample: relative to the pixel where it is brighter than the image's mean, else
  // absolute at the image-mean level: a dark pixel's error is as visible (after tone mapping
  // to the image's exposure) as it is against the mean, and it cannot run forever.
  return standard_error <= threshold_ * std::max({mean, image_mean_, kImageMeanFloor});
}

}  // namespace pdrt
