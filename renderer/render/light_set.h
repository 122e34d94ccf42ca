#pragma once
// The scene's lights (light.h) and the selector that chooses among them (light_selector.h),
// as the path integrator asks for them: a light sample at a shading point, the pdf of a point
// BSDF sampling hit on an emitter or of an escaping direction (for MIS), and the radiance
// emitters and the environment send.
#include "renderer/render/light.h"
#include "renderer/render/light_selector.h"

#include <array>
#include <cstddef>

namespace pdrt {

class LightSet {
 public:
  // textures: the scene's, opened once (MaterialSet owns them); textured emitters read them.
  LightSet(const EmbreeScene& scene, const TextureSet& textures);
  bool empty() const { return lights_.empty(); }
  // Whether sample()'s pick number can change what it returns: not with one light (the
  // selector's only choice; a pick of 1.0f, which a float rounding of a sample value near 1
  // gives, used to refuse a lone light at infinity).
  bool pick_matters() const { return selector_.size() > 1; }

  // u_pick chooses the light for the shading point `ref` with unit shading normal `n`
  // (either side); u samples a point on it. out->pdf includes the choice.
  bool sample(const Vec3& ref, const Vec3& n, float time, float u_pick, std::array<double, 2> u,
              LightSample* out) const;

  // Solid-angle pdf that sample() at (ref, n) would have produced the emitter point `hit`
  // (for MIS after BSDF sampling hit an emitter), and the pdf of the environment in the
  // unit direction w (after a BSDF-sampled ray escaped).
  float pdf(const Vec3& ref, const Vec3& n, const SurfaceHit& hit, float time) const;
  float environment_pdf(const Vec3& ref, const Vec3& n, const Vec3& w) const;

  // Radiance leaving an emitter at `hit` toward the ray that found it (0 for non-emitters and
  // back faces of one-sided emitters).
  Vec3 emitted(const SurfaceHit& hit) const;
  // Whether rays that escape see any environment, and its radiance from the direction w.
  bool has_environment() const { return environment_.visible(); }
  Vec3 environment(const Vec3& w) const { return environment_.radiance(w); }
  const EnvironmentLight& environment_light() const { return environment_; }

  // Light ids as in SceneLights (light.h); the environment's is light_count() when it emits
  // nothing.
  std::size_t light_count() const { return lights_.size(); }
  std::size_t environment_id() const { return environment_id_; }
  const LightSelector& selector() const { return selector_; }

 private:
  const EmbreeScene& scene_;
  const TextureSet& textures_;
  std::vector<Light> lights_;
  std::vector<int64_t> first_light_;  // per shape: id of its first light, or -1
  EnvironmentLight environment_;
  std::size_t environment_id_ = 0;
  bool environment_sampled_ = false;  // the environment is among lights_ (SceneLights)
  LightSelector selector_;
};

}  // namespace pdrt
