#pragma once
// Distribution ray tracing as a path tracer (Cook §5.3, pbrt-v4 PathIntegrator): at every
// vertex, next-event estimation toward a light chosen from the light family, BSDF sampling
// from the gloss family, multiple importance sampling (power heuristic) between them, and
// Russian roulette from `rr_depth`. With `regularize`, vertices after the first non-delta
// scattering shade with regularized materials (bsdf.h). Every random decision comes from the
// replayable sampler, from the stream sample_dimensions.h names for it.
#include "renderer/render/bsdf.h"
#include "renderer/render/embree_scene.h"
#include "renderer/render/light_set.h"
#include "renderer/render/material_set.h"
#include "renderer/render/sample_dimensions.h"
#include "sampling/samplers/sampler.h"

#include <vector>

namespace pdrt {

struct PathResult {
  Vec3 radiance;
  Vec3 albedo;       // first visible surface (AOV)
  Vec3 normal;       // first visible surface shading normal (AOV)
  float depth = 0;   // distance to the first visible surface (AOV; infinity on a miss)
  int64_t rays = 0;  // rays traced: extension + shadow
};

class PathIntegrator {
 public:
  PathIntegrator(const EmbreeScene& scene, const LightSet& lights, const MaterialSet& materials,
                 const IntegratorDesc& settings);
  PathResult trace(Ray ray, const PixelSampleState& sampler) const;
  // The same path when the camera ray's intersection is already known (`found` false: it
  // missed), e.g. from a packet of a pixel's camera rays.
  PathResult trace(Ray ray, const PixelSampleState& sampler, const SurfaceHit& first, bool found) const;

 private:
  PathResult trace(Ray ray, const PixelSampleState& sampler, const SurfaceHit* first, bool found) const;
  const EmbreeScene& scene_;
  const LightSet& lights_;
  const MaterialSet& materials_;
  IntegratorDesc settings_;
  // Whether a ray's hit can emit (the scene has an emitter material): without one, the vertex
  // at max_depth adds light only when its ray escapes, which an occlusion ray decides.
  bool hits_can_emit_ = true;
};

}  // namespace pdrt
