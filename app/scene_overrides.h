#pragma once
// The render settings a command line lays over a scene's own: `render`'s --spp, --sampler,
// --seed, --width, --height, --reconstruction, the adaptive options and --regularize /
// --no-regularize, and the part of them `compare` has (so also a plan's `run-job` and
// `collect`, which rebuild compare's request). One struct, one check of the names before
// anything is loaded, one way of laying them over the scene, and the scene validator after
// (renderer/scene/render_settings.h).
#include "renderer/scene/scene_desc.h"

#include <optional>
#include <string>

namespace pdrt::cli {

struct SceneOverrides {
  std::optional<int> spp, width, height;
  std::optional<uint64_t> seed;
  std::string sampler, reconstruction;  // names; empty: the scene's
  bool adaptive = false;                // adaptive refinement on (any adaptive option below turns it on too)
  std::optional<int> min_spp, max_spp;
  std::optional<double> threshold;
  std::string metric, variance, decision;  // names; empty: the scene's
  std::optional<bool> regularize;
};

// UsageError naming the option for a name no table has (--sampler, --reconstruction,
// --adaptive-metric, --adaptive-variance, --adaptive-decision) or a threshold not > 0.
void check_override_names(const SceneOverrides& o);

// Whether `o` has --adaptive or any adaptive option (each turns adaptive refinement on).
bool adaptive_requested(const SceneOverrides& o);
// --spp without an adaptive option asks for that many samples in every pixel: true when it
// turns off the scene's own adaptive refinement.
bool spp_turns_adaptive_off(const SceneOverrides& o, const SceneDesc& scene);

// Lays `o` over `scene` (the names checked by check_override_names).
void apply_overrides(const SceneOverrides& o, SceneDesc& scene);

// The scene validator on settings the command line changed: a broken rule is a UsageError,
// except an empty crop window, an InputError after film.size_where (the film's size is the scene's).
void check_overridden_settings(const SceneDesc& scene);

}  // namespace pdrt::cli
