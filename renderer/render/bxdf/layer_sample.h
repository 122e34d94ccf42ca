#pragma once
// What one layer of a layered BSDF (layered.h) returns when sampled, in pbrt-v4's terms: the
// BSDF value f and the pdf apart (the random walk multiplies them separately), not their ratio
// as BsdfSample does. Plus the two switches pbrt-v4's BxDF interface adds for the walk: which
// lobes a sample may take (transmission only to enter or leave the slab, reflection only to
// stay inside) and the transport mode (the 1/eta^2 radiance scaling applies to radiance only,
// not to importance, i.e. a virtual light path traced from wi; Veach 1997 §5.2).
#include "renderer/scene/vec3.h"

namespace pdrt {

enum class Transport { Radiance, Importance };

// Lobes a layer may sample (and whose pdf counts): bit flags.
inline constexpr int kLayerReflect = 1, kLayerTransmit = 2, kLayerBoth = 3;

struct LayerSample {
  Vec3 f{0.0f};  // the BSDF value, without the cosine
  Vec3 wi;
  float pdf = 0;  // solid angle, or the discrete probability of a specular lobe
  bool specular = false;
  bool transmission = false;
};

// pbrt-v4's TrowbridgeReitzDistribution::EffectivelySmooth: below this alpha a GGX lobe is a delta.
inline constexpr float kEffectivelySmoothAlpha = 1e-3f;

}  // namespace pdrt
