#include "renderer/render/adaptive_metric.h"

#include "sampling/core/errors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pdrt {

namespace {

// Floors that keep a black pixel (or image) from demanding an error of 0.
constexpr double kRelativeFloor = 1e-3;
constexpr double kImageMeanFloor = 1e-4;

}  // namespace

double default_threshold(AdaptiveMetricKind metric) {
  switch (metric) {
    case AdaptiveMetricKind::ErrorPerSample:
      return 1.0 / 16;
    case AdaptiveMetricKind::RelativeError:
      return 0.01;
    case AdaptiveMetricKind::Contrast:
      return 0.4;
  }
  return 0;
}

double effective_threshold(const AdaptiveDesc& ad) {
  return ad.threshold > 0 ? double(ad.threshold) : default_threshold(ad.metric);
}

AdaptiveMetric::AdaptiveMetric(const AdaptiveDesc& ad)
    : kind_(ad.metric), halves_(ad.variance == AdaptiveVariance::Halves), threshold_(effective_threshold(ad)) {}

bool AdaptiveMetric::converged(const PixelAccum& p) const {
  if (p.samples < 2 || p.w == 0) return false;  // no spread to judge yet
  if (kind_ == AdaptiveMetricKind::Contrast) {
    // Mitchell (1987): per-channel thresholds t, 0.75 t, 1.5 t (0.4/0.3/0.6 for t = 0.4).
    const double scale[3] = {1.0, 0.75, 1.5};
    for (int k = 0; k < 3; ++k)
      if (p.contrast(k) > threshold_ * scale[k]) return false;
    return true;
  }
  const double var_of_mean = halves_ ? p.half_variance_of_mean() : p.variance_of_mean();
  if (kind_ == AdaptiveMetricKind::RelativeError)
    return std::sqrt(var_of_mean) <= threshold_ * std::max(std::abs(p.mean_luminance()), kRelativeFloor);
  // error-per-sample: sqrt(V/n) with V the variance of the mean, i.e. sigma / n. One more
  // sample lowers the pixel's squared error by about sigma^2 / n^2, so stopping every pixel at
  // the same sigma / n spends the budget where it buys the most (n ~ sigma, the allocation
  // that minimises the image's MSE). The reference is the image's mean brightness, so the
  // threshold means the same at any exposure; a pixel's own mean is not used, because that
  // would starve bright, noisy pixels that dominate the error (measured in docs/renderer.md).
  const double n = p.w * p.w / p.w2;
  return std::sqrt(var_of_mean / n) <= threshold_ * std::max(image_mean_, kImageMeanFloor);
}

}  // namespace pdrt
