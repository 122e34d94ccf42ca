#pragma once
// The BSDF a Material describes: one BxDF struct per lobe (renderer/render/bxdf/) behind a
// closed variant, in the local shading frame (normal = +z). wo points away from the surface,
// toward the viewer; wi toward the light. Opaque materials reflect only when wo.z > 0 and
// wi.z > 0; dielectrics treat wo.z > 0 as outside and scale transmitted radiance by 1/eta^2
// (camera-path radiance transport, as pbrt-v4's TransportMode::Radiance).
//   Diffuse         LambertBxdf (lambert.h)
//   Glossy          GgxReflectionBxdf::glossy (ggx_reflection.h: Schlick Fresnel with F0 =
//                   albedo), or PhongBxdf (phong.h) with `lobe: "phong"`
//   Conductor       GgxReflectionBxdf::conductor (exact conductor Fresnel), roughness 0:
//                   SmoothConductorBxdf (specular_reflection.h)
//   Mirror          SchlickMirrorBxdf (specular_reflection.h)
//   Dielectric      RoughDielectricBxdf (rough_dielectric.h); roughness 0 or index 1:
//                   SmoothDielectricBxdf (smooth_dielectric.h)
//   ThinDielectric  ThinDielectricBxdf (thin_dielectric.h)
//   CoatedDiffuse   CoatedDiffuse (coated_diffuse.h): a smooth coat is one delta lobe beside a
//                   non-delta one: is_delta() is false, eval() and pdf() give the non-delta
//                   part, sample() flags the delta reflection
//                   With "layered" (Material::layered): LayeredBxdf (layered.h)
//   CoatedConductor LayeredBxdf (layered.h), pbrt-v4's CoatedConductorBxDF
//   Emitter, Mix    BlackBxdf (a Mix is resolved to a component per hit before, mix_material.h)
// A new lobe is a struct with kDelta, eval, pdf and sample in its own file, one alternative in
// BxdfVariant and the case of its material in Bsdf::Bsdf (bsdf.cpp). A stochastic lobe
// (LayeredBxdf) sets kKeyed and takes the caller's key as the last argument of eval, pdf and
// sample (after out); a lobe whose deltas depend on its parameters has delta().
#include "renderer/render/bxdf/black.h"
#include "renderer/render/bxdf/bsdf_sample.h"
#include "renderer/render/bxdf/coated_diffuse.h"
#include "renderer/render/bxdf/ggx_reflection.h"
#include "renderer/render/bxdf/lambert.h"
#include "renderer/render/bxdf/layered.h"
#include "renderer/render/bxdf/phong.h"
#include "renderer/render/bxdf/rough_dielectric.h"
#include "renderer/render/bxdf/smooth_dielectric.h"
#include "renderer/render/bxdf/specular_reflection.h"
#include "renderer/render/bxdf/thin_dielectric.h"
#include "renderer/scene/material.h"
#include "renderer/scene/vec3.h"

#include <cstdint>
#include <type_traits>
#include <variant>

namespace pdrt {

using BxdfVariant =
    std::variant<BlackBxdf, LambertBxdf, GgxReflectionBxdf, PhongBxdf, SchlickMirrorBxdf, SmoothConductorBxdf,
                 SmoothDielectricBxdf, RoughDielectricBxdf, CoatedDiffuse, ThinDielectricBxdf, LayeredBxdf>;

// Lobes whose eval, pdf and sample are random estimates take a key (LayeredBxdf).
template <class B>
concept KeyedBxdf = B::kKeyed;

class Bsdf {
  BxdfVariant bxdf_;
  Vec3 albedo_{0.0f};

  // f(lobe, key) for a keyed lobe, f(lobe) for the others.
  template <class F>
  auto with_key(uint64_t key, F&& f) const {
    return std::visit(
        [&](const auto& b) {
          if constexpr (KeyedBxdf<std::decay_t<decltype(b)>>)
            return f(b, key);
          else
            return f(b);
        },
        bxdf_);
  }
  // query(lobe) where the lobe answers it (query's return type fails for the others),
  // otherwise(lobe) for the rest.
  template <class Query, class Otherwise>
  bool ask(Query&& query, Otherwise&& otherwise) const {
    return std::visit(
        [&](const auto& b) -> bool {
          if constexpr (std::is_invocable_v<Query, decltype(b)>)
            return query(b);
          else
            return otherwise(b);
        },
        bxdf_);
  }

 public:
  explicit Bsdf(const Material& m);  // Emitter (and unresolved Mix) material -> a black, non-scattering BSDF

  // `key` seeds the random walks of a stochastic lobe (PixelSampleState::walk_key: a hash of
  // seed, pixel, sample index and vertex); the other lobes ignore it.
  // f(wo, wi), without the cosine; 0 for delta lobes.
  Vec3 eval(const Vec3& wo, const Vec3& wi, uint64_t key = 0) const {
    return with_key(key, [&](const auto& b, auto... k) { return b.eval(wo, wi, k...); });
  }
  // Solid-angle pdf that sample() produces wi (non-delta part); a stochastic lobe's estimate for MIS.
  float pdf(const Vec3& wo, const Vec3& wi, uint64_t key = 0) const {
    return with_key(key, [&](const auto& b, auto... k) { return b.pdf(wo, wi, k...); });
  }
  // u1, u2 in [0, 1) choose the direction, uc in [0, 1) the lobe (Fresnel reflect vs transmit).
  // False when no direction is produced (below the horizon, wo grazing, non-scattering).
  bool sample(const Vec3& wo, float u1, float u2, float uc, BsdfSample* out, uint64_t key = 0) const {
    *out = BsdfSample{};
    return with_key(key, [&](const auto& b, auto... k) { return b.sample(wo, u1, u2, uc, out, k...); });
  }

  // Every lobe is a delta (mirror, conductor or dielectric with roughness 0, thin dielectric,
  // a layered lobe of smooth layers only).
  bool is_delta() const {
    return ask([](const auto& b) -> decltype(b.delta()) { return b.delta(); },
               [](const auto& b) { return std::decay_t<decltype(b)>::kDelta; });
  }
  // Whether sample() reads its lobe choice uc and its direction u1, u2: a lobe that ignores
  // one says so (uses_lobe_choice() / uses_direction() false), and the path tracer then does
  // not draw it (each decision is a stream of its own, so no other value moves).
  bool uses_lobe_choice() const {
    return ask([](const auto& b) -> decltype(b.uses_lobe_choice()) { return b.uses_lobe_choice(); },
               [](const auto&) { return true; });
  }
  bool uses_direction() const {
    return ask([](const auto& b) -> decltype(b.uses_direction()) { return b.uses_direction(); },
               [](const auto&) { return true; });
  }
  bool scatters() const { return !std::holds_alternative<BlackBxdf>(bxdf_); }  // false for emitters
  Vec3 albedo() const { return albedo_; }                                      // for the albedo AOV
};

// Path regularisation (IntegratorDesc::regularize; Kaplanyan & Dachsbacher 2013, as pbrt-v4's
// `regularize` option does it): the material a vertex shades with once the path has scattered
// off a non-delta lobe. A GGX alpha below 0.3 becomes clamp(2 alpha, 0.1, 0.3) (glossy,
// conductor, dielectric and the coated_diffuse coat; roughness 0 counts as alpha 0, so smooth
// ones become rough at alpha 0.1); a mirror becomes the GGX glossy of its F0 at alpha 0.1; a
// Phong lobe gets the exponent of that alpha (n = 2 / alpha^2 - 2, Walter et al. 2007). Diffuse,
// thin dielectric (whose transmission keeps its direction), emitter and mix materials are
// unchanged. Biased: near-specular caustics blur; never on unless asked.
Material regularized(const Material& m);
inline constexpr float kRegularizeAlphaMax = 0.3f;
inline constexpr float kRegularizeAlphaMin = 0.1f;

}  // namespace pdrt
