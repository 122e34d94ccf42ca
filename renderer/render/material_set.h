#pragma once
// The scene's materials at render time: the owner of the scene's textures (opened once; the
// light set borrows them for textured emitters), the BSDF of every material built once (and
// its regularised twin when the integrator regularises), and the shading at a hit in one call:
// a mix resolved to one component (mix_material.h), texture bindings evaluated at the hit's
// footprint (texture_footprint.h) into a BSDF built for that hit.
#include "renderer/render/bsdf.h"
#include "renderer/render/embree_scene.h"
#include "renderer/render/texture_footprint.h"
#include "renderer/render/texture_set.h"

#include <optional>
#include <vector>

namespace pdrt {

class MaterialSet {
 public:
  // regularize: also build regularized(material) of each (IntegratorDesc::regularize).
  MaterialSet(const EmbreeScene& scene, const TextureFootprint& footprint, bool regularize);
  const TextureSet& textures() const { return textures_; }
  bool regularizes() const { return regularize_; }

  struct Shading {
    const Material* material = nullptr;  // the material shading the hit (a mix's chosen component)
    std::optional<Bsdf> owned;           // a textured material's BSDF, built for this hit
    const Bsdf* shared = nullptr;        // otherwise the material's own
    const Bsdf& bsdf() const { return owned ? *owned : *shared; }
  };
  // The shading of `hit`, seen from wo_world at `time`; `regularize`: with regularized
  // materials. Fills in hit's texture coordinates when a texture or a mix needs them.
  Shading at(SurfaceHit& hit, const Vec3& wo_world, float time, bool regularize) const;

 private:
  const EmbreeScene& scene_;
  TextureSet textures_;
  TextureFootprint footprint_;
  std::vector<Bsdf> bsdfs_;        // per material (textured ones: with their constant values, unused)
  std::vector<Bsdf> regularized_;  // per material, regularized(material) (regularize only)
  // Textured materials build their Bsdf per hit from `bare_` (the material without name and
  // bindings, so that the copy allocates nothing) with the textures evaluated at the hit.
  std::vector<Material> bare_;
  bool regularize_;
};

}  // namespace pdrt
