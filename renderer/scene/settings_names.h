#pragma once
// The render settings' vocabularies: each enum with its one name table, read wherever the
// names are parsed (scene files, command lines, plans) or printed (help, messages, reports,
// metadata). Samplers have theirs in sampling/samplers/sampler_names.h (kSamplerNames).
#include "sampling/core/name_table.h"

#include <iterator>
#include <string>

namespace pdrt {

// How samples become pixels (docs/renderer.md, "Reconstruction"):
//   Importance  offsets drawn in proportion to |f|, weight sign(f) * integral |f| (pbrt-v4)
//   Splat       the image-plane pattern at pixel scale; each sample feeds every pixel whose
//               filter covers it (Cook §4.2)
//   Rank        offsets uniform over the support, kept when a randomised rank is below the
//               normalised filter value (McCool–Fiume §5.2)
enum class Reconstruction { Importance, Splat, Rank };
inline constexpr NamedValue<Reconstruction> kReconstructionNames[] = {
    {Reconstruction::Importance, "importance"}, {Reconstruction::Splat, "splat"}, {Reconstruction::Rank, "rank"}};

// Adaptive refinement (sampler.adaptive; render/adaptive_metric.h gives the metrics and
// variance estimators their meaning), in the order messages list them.
// metric: when a pixel has converged.
enum class AdaptiveMetricKind { ErrorPerSample, RelativeError, Contrast };
inline constexpr NamedValue<AdaptiveMetricKind> kAdaptiveMetricNames[] = {
    {AdaptiveMetricKind::ErrorPerSample, "error-per-sample"},
    {AdaptiveMetricKind::RelativeError, "relative-error"},
    {AdaptiveMetricKind::Contrast, "contrast"}};
// variance: how the variance of a pixel's mean is estimated.
enum class AdaptiveVariance { Samples, Halves };
inline constexpr NamedValue<AdaptiveVariance> kAdaptiveVarianceNames[] = {{AdaptiveVariance::Samples, "samples"},
                                                                          {AdaptiveVariance::Halves, "halves"}};
// decision: shared, every sample both decides and estimates (Kirk-Arvo biased); split, odd
// samples decide, even samples estimate (unbiased, half the samples in the image).
enum class AdaptiveDecision { Shared, Split };
inline constexpr NamedValue<AdaptiveDecision> kAdaptiveDecisionNames[] = {{AdaptiveDecision::Shared, "shared"},
                                                                          {AdaptiveDecision::Split, "split"}};

// How next-event estimation samples the environment (integrator.environment_sampling):
//   Full         a constant environment uniformly, an image in proportion to its luminance
//   Compensated  pbrt-v4's path integrator (allowIncompletePDF; Karlik et al. 2019, "MIS
//                compensation"): a constant environment is left to BSDF sampling, an image is
//                sampled in proportion to max(luminance - its mean, 0)
enum class EnvironmentSampling { Full, Compensated };
inline constexpr NamedValue<EnvironmentSampling> kEnvironmentSamplingNames[] = {
    {EnvironmentSampling::Full, "full"}, {EnvironmentSampling::Compensated, "compensated"}};

static_assert(covers_in_order(kReconstructionNames) && std::size(kReconstructionNames) == 3);
static_assert(covers_in_order(kAdaptiveMetricNames) && std::size(kAdaptiveMetricNames) == 3);
static_assert(covers_in_order(kAdaptiveVarianceNames) && std::size(kAdaptiveVarianceNames) == 2);
static_assert(covers_in_order(kAdaptiveDecisionNames) && std::size(kAdaptiveDecisionNames) == 2);
static_assert(covers_in_order(kEnvironmentSamplingNames) && std::size(kEnvironmentSamplingNames) == 2);

inline const char* reconstruction_name(Reconstruction r) { return name_in(kReconstructionNames, r); }
inline const char* adaptive_metric_name(AdaptiveMetricKind m) { return name_in(kAdaptiveMetricNames, m); }
inline const char* adaptive_variance_name(AdaptiveVariance v) { return name_in(kAdaptiveVarianceNames, v); }
inline const char* adaptive_decision_name(AdaptiveDecision d) { return name_in(kAdaptiveDecisionNames, d); }
inline const char* environment_sampling_name(EnvironmentSampling e) { return name_in(kEnvironmentSamplingNames, e); }

// False for a name the table lacks.
inline bool parse_reconstruction(const std::string& name, Reconstruction* out) {
  return parse_name_in(kReconstructionNames, name, out);
}

}  // namespace pdrt
