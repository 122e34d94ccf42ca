#pragma once
// The mix material (docs/scene-format.md, "mix"): pbrt-v4's MixMaterial (pbrt-v4
// src/pbrt/materials.h, MixMaterial::ChooseMaterial). At each shading point it *is* one of its
// two materials: the second with probability `amount`, chosen by a hash of the hit point, the
// outgoing direction and the nesting level (not the mix's index, so that renumbering the
// materials, as pdrt convert does, keeps the image), not by a sampler dimension: the choice
// is replayable and uses no sample the component's BSDF would otherwise get.
//
// Why choosing rather than blending the BSDFs (Mitsuba 3's blendbsdf: f = (1 - a) f0 + a f1,
// sample one by a, pdf the mixture): both have the expectation (1 - a) f0 + a f1 over the
// choice, but pdrt's path integrator builds one Bsdf value per hit and decides per material
// whether the shading frame keeps the outward normal (dielectrics) or faces the ray (opaque).
// A choice keeps every component exactly as it is: delta lobes, dielectric frames, textures,
// energy compensation, next-event estimation and MIS against the component's own pdf, and
// nested mixes are a loop. A blend would need a nested Bsdf and a frame for a glass/diffuse
// mixture. The price is variance between neighbouring hits, which the pixel's samples average.
#include "renderer/scene/material.h"

#include <vector>

namespace pdrt {

// A uniform number in [0, 1) from the hit point, the direction toward the viewer and the
// nesting level (0 for the shape's own mix, 1 for a mix inside it, ...).
float mix_hash(const Vec3& p, const Vec3& wo, int level);

// 0 (the first material) or 1: amount <= 0 always 0, amount >= 1 always 1, else 1 iff u < amount.
inline int mix_component(float amount, float u) { return amount >= 1 ? 1 : (u < amount ? 1 : 0); }

// The non-mix material that material `mi` stands for at the hit (mi itself when it is no mix);
// nested mixes resolve in turn, each level with its own hash. amount_at(k) is mix k's amount there.
// Terminates: the loaders refuse cycles of mixes.
template <class AmountAt>
int resolve_mix(const std::vector<Material>& materials, int mi, const Vec3& p, const Vec3& wo, AmountAt&& amount_at) {
  for (int level = 0; materials[size_t(mi)].type == MaterialType::Mix; ++level) {
    const Material& m = materials[size_t(mi)];
    mi = m.mix[mix_component(amount_at(mi), mix_hash(p, wo, level))];
  }
  return mi;
}

}  // namespace pdrt
