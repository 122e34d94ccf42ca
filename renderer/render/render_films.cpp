#include "renderer/render/render_films.h"

#include "renderer/render/renderer.h"
#include "sampling/core/derived_seeds.h"
#include "sampling/core/rng.h"

namespace pdrt {

std::unique_ptr<Sampler> make_decision_sampler(const SamplerDesc& scene_sampler, const FilmDesc& film,
                                               const Sampler& sampler) {
  SamplerDesc d = scene_sampler;
  d.type = sampler.name(), d.seed = decider_seed(sampler.seed());
  return make_scene_sampler(d, film);
}

}  // namespace pdrt
