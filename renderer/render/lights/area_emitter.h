#pragma once
// What triangle and sphere lights share: the emitting shape, read where Embree intersects it
// (a moving shape at the ray's time), and its emitter material, whose radiance may be a
// texture.
#include "renderer/render/embree_scene.h"
#include "renderer/render/texture_set.h"

namespace pdrt {

// An emitter's radiance at a point of shape `h.shape` (triangles: h.prim and Embree's
// barycentrics; spheres: h.p_local), its `radiance` texture evaluated there if it has one.
Vec3 emitter_radiance(const EmbreeScene& scene, const TextureSet& textures, const Material& m, SurfaceHit h);
// Luminance of an emitter's radiance for light selection: a textured one's mean over uv.
float emitter_luminance(const TextureSet& textures, const Material& m);

struct AreaEmitter {
  const EmbreeScene* scene = nullptr;
  const TextureSet* textures = nullptr;  // the scene's (MaterialSet's)
  int shape = -1;
  float luminance = 0;  // max(emitter_luminance, 1e-6): the selection's, once per shape

  const Material& material() const { return scene->desc().materials[scene->desc().shapes[shape].material]; }
  Vec3 radiance(const Material& m, const SurfaceHit& h) const { return emitter_radiance(*scene, *textures, m, h); }
};

}  // namespace pdrt
