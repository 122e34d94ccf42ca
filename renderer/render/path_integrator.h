#pragma once
// Distribution ray tracing as a path tracer (Cook §5.3, pbrt-v4 PathIntegrator): at every
// vertex, next-event estimation toward a light chosen from the light family, BSDF sampling
// from the gloss family, multiple importance sampling (power heuristic) between them, and
// Russian roulette from `rr_depth`. With `regularize`, vertices after the first non-delta
// scattering shade with regularized materials (bsdf.h). Every random decision comes from the
// replayable sampler: 2-D values from the light and gloss families with the vertex index as the bounce salt,
// 1-D decisions (which light, which lobe, roulette) from salted time-family streams.
#include "renderer/render/bsdf.h"
#include "renderer/render/embree_scene.h"
#include "renderer/render/light_sampler.h"
#include "renderer/render/material_set.h"
#include "sampling/samplers/sampler.h"

#include <vector>

namespace pdrt {

struct PathResult {
  Vec3 radiance;
  Vec3 albedo;      // first visible surface (AOV)
  Vec3 normal;      // first visible surface shading normal (AOV)
  float depth = 0;  // distance to the first visible surface (AOV; infinity on a miss)
  int64_t rays = 0; // rays traced: extension + shadow
};

class PathIntegrator {
 public:
  PathIntegrator(const EmbreeScene& scene, const LightSampler& lights, const MaterialSet& materials,
                 const IntegratorDesc& settings);
  PathResult trace(Ray ray, const PixelSampleState& sampler) const;
  // The same path when the camera ray's intersection is already known (`found` false: it
  // missed), e.g. from a packet of a pixel's camera rays.
  PathResult trace(Ray ray, const PixelSampleState& sampler, const SurfaceHit& first, bool found) const;

 private:
  PathResult trace(Ray ray, const PixelSampleState& sampler, const SurfaceHit* first, bool found) const;
  const EmbreeScene& scene_;
  const LightSampler& lights_;
  const MaterialSet& materials_;
  IntegratorDesc settings_;
};

// Sampler salts of the 1-D decisions at path vertex `depth` (time family, bounce >= 1;
// bounce 0 of the time family is the shutter time).
inline int salt_light_pick(int depth) { return 1 + 3 * depth; }
inline int salt_lobe(int depth) { return 2 + 3 * depth; }
inline int salt_roulette(int depth) { return 3 + 3 * depth; }

}  // namespace pdrt
