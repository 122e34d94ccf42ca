#pragma once
// When a pixel of an adaptive render has converged: the metrics of `sampler.adaptive.metric`,
// their default thresholds, and the `variance` estimators they read (docs/renderer.md). The
// names are scene/settings_names.h's.
#include "renderer/render/film.h"
#include "renderer/scene/scene_desc.h"

#include <string>

namespace pdrt {

// Each metric's own default: error-per-sample 1/16, relative-error 0.01, contrast 0.4.
double default_threshold(AdaptiveMetricKind metric);

// The threshold in force: the scene's (or command line's) if given, else the metric's default.
double effective_threshold(const AdaptiveDesc& ad);

class AdaptiveMetric {
 public:
  explicit AdaptiveMetric(const AdaptiveDesc& ad);

  // error-per-sample compares against the image's mean luminance; call before converged()
  // with the mean over all pixels of the current round.
  void set_image_mean(double mean_luminance) { image_mean_ = mean_luminance; }
  bool needs_image_mean() const { return kind_ == AdaptiveMetricKind::ErrorPerSample; }

  bool converged(const PixelAccum& p) const;

 private:
  AdaptiveMetricKind kind_;
  bool halves_;
  double threshold_;
  double image_mean_ = 0;
};

}  // namespace pdrt
