#pragma once
// Next-event estimation targets (Cook §5.3 "light area" dimension): every emissive triangle,
// every emissive sphere, every point and spot light (in the light BVH, light_bvh.h), and the
// distant lights and the environment (outside it, on the same footing), chosen by their
// estimated contribution at the shading point. Triangles are sampled uniformly by area,
// spheres by the cone they subtend, a constant environment uniformly over the sphere of
// directions, an environment image by its luminance x sin(theta) (environment_map.h; its
// selection importance is pi x its solid-angle mean luminance, the irradiance a constant
// environment of that luminance delivers); point, spot and distant lights are delta
// lights: one direction, weight 1, no MIS. Moving
// emitters are sampled where they are at the ray's time, using the same transform Embree
// intersects.
#include "renderer/render/embree_scene.h"
#include "renderer/render/environment_map.h"
#include "renderer/render/light_bvh.h"
#include "renderer/render/texture_set.h"

#include <array>
#include <memory>
#include <cmath>
#include <vector>

namespace pdrt {

struct LightSample {
  Vec3 wi;          // unit direction from the reference point to the light
  float dist = 0;   // distance to the sampled point (1e30 for the environment)
  bool at_infinity = false;  // the environment, a distant light: no point to aim the shadow ray at
  bool delta = false;        // a point, spot or distant light: no MIS (weight 1); pdf is the pick probability
  ErrorPoint x;     // the sampled point on an area light, with its error bound (shadow rays end there)
  Vec3 n;           // the light's geometric normal at x
  Vec3 radiance;    // emitted radiance toward the reference point (0 if back-facing)
  float pdf = 0;    // solid-angle pdf, including the choice of this light
};

class LightSampler {
 public:
  // textures: the scene's, opened once (MaterialSet owns them); textured emitters read them.
  LightSampler(const EmbreeScene& scene, const TextureSet& textures);
  bool empty() const { return light_count() == 0; }

  // u_pick chooses the light for the shading point `ref` with unit shading normal `n`
  // (either side); u samples a point on it.
  bool sample(const Vec3& ref, const Vec3& n, float time, float u_pick, std::array<double, 2> u,
              LightSample* out) const;

  // Solid-angle pdf that sample() at (ref, n) would have produced the emitter point `hit`
  // (for MIS after BSDF sampling hit an emitter), and the pdf of the environment in the
  // unit direction w (after a BSDF-sampled ray escaped).
  float pdf(const Vec3& ref, const Vec3& n, const SurfaceHit& hit, float time) const;
  float environment_pdf(const Vec3& ref, const Vec3& n, const Vec3& w) const;

  // Light selection alone. Light ids: 0 .. light_count() - 1, one per emissive triangle or
  // sphere in shape order, then the point and spot lights (the BVH's), then the distant
  // lights, then the environment (if it emits). Lights of zero power are left out.
  std::size_t light_count() const { return environment_id() + (env_irradiance_ > 0 ? 1 : 0); }
  std::size_t environment_id() const { return entries_.size() + distant_.size(); }
  bool select(const Vec3& ref, const Vec3& n, float u, std::size_t* light, float* pmf) const;
  float select_pmf(const Vec3& ref, const Vec3& n, std::size_t light) const;

  // Radiance leaving an emitter at `hit` toward the ray that found it (0 for non-emitters and
  // back faces of one-sided emitters).
  Vec3 emitted(const SurfaceHit& hit) const;
  // Whether rays that escape see any environment, and its radiance from the direction w.
  bool has_environment() const { return !map_.empty() || !is_black(env_); }
  Vec3 environment(const Vec3& w) const { return map_.empty() ? env_ : map_.radiance(w); }
  const EnvironmentMap& environment_map() const { return map_; }

 private:
  struct Entry {
    int shape;       // the emitting shape, -1 for a point or spot light
    int prim;        // triangle index, -1 for spheres
    int delta = -1;  // point or spot light: index into SceneDesc::delta_lights
  };
  struct Distant {
    Vec3 to_light;   // unit, against the direction the light travels
    Vec3 irradiance;
    float lum;       // luminance of the irradiance (> 0)
  };
  // Importance of the lights outside the BVH at a point of shading normal n: distant light k
  // (k < distant_.size()) delivers E = luminance |cos|, the environment pi luminance.
  float infinite_importance(std::size_t k, const Vec3& n) const {
    return k < distant_.size() ? distant_[k].lum * std::abs(dot(n, distant_[k].to_light)) : env_irradiance_;
  }
  std::size_t infinite_count() const { return distant_.size() + (env_irradiance_ > 0 ? 1 : 0); }
  // World position and unit axis (spot lights) of a point or spot light at the normalised time.
  void delta_light_at(int delta, float time, Vec3* p, Vec3* axis) const;
  LightBounds delta_bounds(int delta) const;
  bool sample_delta(const Entry& e, const Vec3& ref, float time, LightSample* out) const;
  LightBounds bounds_of(const Entry& e) const;
  // World-space corners of a triangle of `shape` at the normalised shutter time.
  void triangle_at(int shape, int prim, float time, Vec3* a, Vec3* b, Vec3* c) const;
  // The point of that triangle at barycentrics (b1, b2), built where the geometry is stored
  // (instance space for moving shapes) so its error bound includes the transform's.
  ErrorPoint triangle_point_at(int shape, int prim, float time, float b1, float b2) const;
  bool sample_triangle(const Entry& e, const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const;
  bool sample_sphere(const Entry& e, const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const;
  float sphere_pdf(int shape, const Vec3& ref, const Vec3& p, const Vec3& n, float time) const;

  // An emitter's radiance at a point of shape `h.shape` (triangles: h.prim and Embree's
  // barycentrics; spheres: h.p_local), its texture evaluated there when `radiance` is textured.
  Vec3 emitter_radiance(const Material& m, SurfaceHit h) const;
  // Luminance of an emitter's radiance for light selection: a textured one's mean over uv.
  float emitter_luminance(const Material& m) const;

  const EmbreeScene& scene_;
  const TextureSet& textures_;  // the scene's (MaterialSet's): textured emitters read them
  std::vector<Entry> entries_;
  LightBvh bvh_;                      // over entries_ (ids = entry indices)
  std::vector<int64_t> first_entry_;  // per shape: index of its first entry, or -1
  std::vector<Distant> distant_;      // distant lights of non-zero irradiance
  float env_irradiance_ = 0;          // pi x (mean) luminance of the environment, 0 if none
  Vec3 env_;                          // the constant environment
  EnvironmentMap map_;                // or the image (then env_ is black)
};

}  // namespace pdrt
