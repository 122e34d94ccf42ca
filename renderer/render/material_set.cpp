#include "renderer/render/material_set.h"

#include "renderer/render/mix_material.h"

namespace pdrt {

MaterialSet::MaterialSet(const EmbreeScene& scene, const TextureFootprint& footprint, bool regularize)
    : scene_(scene), textures_(scene.desc()), footprint_(footprint), regularize_(regularize) {
  for (const Material& m : scene.desc().materials) {
    bsdfs_.emplace_back(m);
    if (regularize) regularized_.emplace_back(regularized(m));
    bare_.push_back(m);
    bare_.back().name.clear();
    bare_.back().textures.clear();
  }
}

MaterialSet::Shading MaterialSet::at(SurfaceHit& hit, const Vec3& wo_world, float time, bool regularize) const {
  const std::vector<Material>& materials = scene_.desc().materials;
  bool have_coords = false;
  int mi = scene_.material(hit.shape);  // a prototype's shape inside an instance
  if (materials[size_t(mi)].type == MaterialType::Mix) {
    // pbrt-v4's MixMaterial: this hit shades with one component (mix_material.h).
    mi = resolve_mix(materials, mi, hit.p, wo_world, [&](int k) {
      const Material& m = materials[size_t(k)];
      if (m.textures.empty()) return m.amount;
      if (!have_coords) scene_.texture_coords(&hit, time), have_coords = true;
      return textures_.apply(bare_[size_t(k)], m.textures, footprint_.at(hit)).amount;
    });
  }
  Shading s;
  s.material = &materials[size_t(mi)];
  if (!s.material->textures.empty()) {
    if (!have_coords) scene_.texture_coords(&hit, time);
    const Material m = textures_.apply(bare_[mi], s.material->textures, footprint_.at(hit));
    s.owned.emplace(regularize ? regularized(m) : m);
  } else {
    s.shared = regularize ? &regularized_[mi] : &bsdfs_[mi];
  }
  return s;
}

}  // namespace pdrt
