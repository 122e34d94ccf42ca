#pragma once
// The films a render accumulates into, in film coordinates (pixel (x, y) of the image is
// at(x - region.x0, y - region.y0)). Kirk & Arvo (1991): samples that chose when a pixel stops
// bias its estimate, so with adaptive decision "split" they go to a film of their own, drawn
// from a sampler of their own, and only decide.
#include "renderer/render/film.h"
#include "renderer/scene/scene_desc.h"
#include "sampling/samplers/sampler.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace pdrt {

struct RenderFilms {
  RenderFilms(int width, int height, bool split)
      : image(width, height), decision(split ? width : 0, split ? height : 0), split(split) {}

  Film image;     // the estimate
  Film decision;  // the decision samples (empty unless split)
  bool split;

  // The film the adaptive metric judges.
  const Film& judged() const { return split ? decision : image; }
  Film* decision_or_null() { return split ? &decision : nullptr; }
  // Camera samples traced at film pixel (x, y), into either film.
  int64_t traced(int x, int y) const { return image.at(x, y).traced + (split ? decision.at(x, y).traced : 0); }
};

// The decision samples' sampler under "split": `sampler`'s kind, seeded apart from it.
std::unique_ptr<Sampler> make_decision_sampler(const SamplerDesc& scene_sampler, const FilmDesc& film,
                                               const Sampler& sampler);

}  // namespace pdrt
