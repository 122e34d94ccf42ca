#pragma once
// The rules that tie a scene's render settings together (each value's own range is checked
// where it is read). Each rule is written here once; `check_render_settings` runs them all
// after either loader (scene_loader.cpp) and the renderer runs it again, and the command line
// runs `render_settings_problem` after its overrides (app/scene_overrides.h). A loader that
// can point at the setting in its file calls the rule there too, to name the place.
#include "renderer/scene/scene_desc.h"

#include <optional>
#include <string>

namespace pdrt {

// Each rule's complaint, to follow the setting's name; "" when the settings keep the rule.
// sampler.adaptive: "min_spp (8) must be <= max_spp (4)" (adaptive on only).
std::string adaptive_spp_problem(const AdaptiveDesc& ad);
// sampler.adaptive.decision: "\"split\" needs reconstruction \"importance\" or \"splat\", not
// \"rank\"" (adaptive on only): rank selection keeps a candidate by its index among all of the
// pixel's, so the odd and even halves are not each an unbiased estimate.
std::string decision_problem(const AdaptiveDesc& ad, Reconstruction reconstruction);
// film.crop_window: "covers no pixel of the 8x8 film (pixels ceil(size * bound) are [5, 5) x [0, 8))".
std::string crop_window_problem(const FilmDesc& film);

// sampler.type: "\"poisson-ss\" orders 4096x4096 pixels at 1024 spp with 34 bits of Morton and
// sample index, at most 32 (...)" for the samplers that order pixels (orders_pixels); spp is
// the first pass's (adaptive min_spp).
std::string pixel_order_problem(const SamplerDesc& sampler, const FilmDesc& film);

// sampler.type "poisson-ip" (samples_image_plane): "\"poisson-ip\" needs reconstruction
// \"splat\" (...), got \"importance\"", "... cannot refine adaptively (...)", "... takes at most
// 65536 spp (...), got 100000"; spp is the render's.
std::string image_plane_problem(const SamplerDesc& sampler, const FilmDesc& film);

// The sampler's rules above (pixel order, then image plane): compare asks them of every sampler
// and count it sweeps.
std::string sampler_problem(const SamplerDesc& sampler, const FilmDesc& film);

struct SettingsProblem {
  enum class Setting { AdaptiveSpp, AdaptiveDecision, CropWindow, PixelOrder, ImagePlane } setting;
  // The setting named as outside a file: "adaptive: min_spp ...", "adaptive decision \"split\"
  // needs ...", "film.crop_window covers no pixel ...".
  std::string message;
};

// The first rule `s` breaks, in the order above, or nothing.
std::optional<SettingsProblem> render_settings_problem(const SceneDesc& s);

// InputError with the problem's message (the crop window's and the pixel order's after
// film.size_where, which names the film's size in the scene file; the image plane's after
// sampler.type_where).
void check_render_settings(const SceneDesc& s);

}  // namespace pdrt
