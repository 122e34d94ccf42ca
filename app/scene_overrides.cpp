#include "app/scene_overrides.h"

#include "renderer/scene/render_settings.h"
#include "sampling/core/errors.h"
#include "sampling/samplers/sampler.h"

#include <cmath>

namespace pdrt::cli {

namespace {

// The value `text` names in `table`; UsageError "`flag` must be one of a, b, c, got "text"".
template <class E, std::size_t N>
E adaptive_choice(const char* flag, const std::string& text, const NamedValue<E> (&table)[N]) {
  E v{};
  if (!parse_name_in(table, text, &v))
    throw UsageError(std::string(flag) + " must be one of " + name_list(table) + ", got \"" + text + "\"");
  return v;
}

}  // namespace

void check_override_names(const SceneOverrides& o) {
  SamplerKind sampler{};
  if (!o.sampler.empty() && !parse_sampler(o.sampler, &sampler))
    throw UsageError("--sampler: unknown sampler \"" + o.sampler + "\" (" + sampler_name_list() + ")");
  if (o.threshold && !(*o.threshold > 0 && std::isfinite(*o.threshold)))
    throw UsageError("--adaptive-threshold must be > 0, got " + std::to_string(*o.threshold));
  if (!o.metric.empty()) adaptive_choice("--adaptive-metric", o.metric, kAdaptiveMetricNames);
  if (!o.variance.empty()) adaptive_choice("--adaptive-variance", o.variance, kAdaptiveVarianceNames);
  if (!o.decision.empty()) adaptive_choice("--adaptive-decision", o.decision, kAdaptiveDecisionNames);
  Reconstruction recon{};
  if (!o.reconstruction.empty() && !parse_reconstruction(o.reconstruction, &recon))
    throw UsageError("--reconstruction: unknown mode \"" + o.reconstruction + "\" (" + name_list(kReconstructionNames) +
                     ")");
}

bool adaptive_requested(const SceneOverrides& o) {
  return o.adaptive || o.min_spp || o.max_spp || o.threshold || !o.metric.empty() || !o.variance.empty() ||
         !o.decision.empty();
}

bool spp_turns_adaptive_off(const SceneOverrides& o, const SceneDesc& scene) {
  return o.spp && scene.sampler.adaptive.enabled && !adaptive_requested(o);
}

void apply_overrides(const SceneOverrides& o, SceneDesc& scene) {
  check_override_names(o);
  AdaptiveDesc& ad = scene.sampler.adaptive;
  if (spp_turns_adaptive_off(o, scene)) ad.enabled = false;
  ad.enabled = ad.enabled || adaptive_requested(o);
  if (o.min_spp) ad.min_spp = *o.min_spp;
  if (o.max_spp) ad.max_spp = *o.max_spp;
  if (o.threshold) ad.threshold = float(*o.threshold);
  if (!o.metric.empty()) ad.metric = adaptive_choice("--adaptive-metric", o.metric, kAdaptiveMetricNames);
  if (!o.variance.empty()) ad.variance = adaptive_choice("--adaptive-variance", o.variance, kAdaptiveVarianceNames);
  if (!o.decision.empty()) ad.decision = adaptive_choice("--adaptive-decision", o.decision, kAdaptiveDecisionNames);
  if (!o.reconstruction.empty()) parse_reconstruction(o.reconstruction, &scene.film.filter.reconstruction);
  if (o.spp) scene.sampler.spp = *o.spp;
  if (!o.sampler.empty()) scene.sampler.type = o.sampler;
  if (o.seed) scene.sampler.seed = *o.seed;
  if (o.width) scene.film.width = *o.width;
  if (o.height) scene.film.height = *o.height;
  if (o.regularize) scene.integrator.regularize = *o.regularize;
}

void check_overridden_settings(const SceneDesc& scene) {
  const std::optional<SettingsProblem> p = render_settings_problem(scene);
  if (!p) return;
  if (p->setting == SettingsProblem::Setting::CropWindow) throw InputError(scene.film.size_where + ": " + p->message);
  throw UsageError(p->message);
}

}  // namespace pdrt::cli
