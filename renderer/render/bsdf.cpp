#include "renderer/render/bsdf.h"

#include "renderer/render/fresnel.h"
#include "renderer/render/ggx_albedo_tables.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

Bsdf::Bsdf(const Material& m) : albedo_(m.albedo) {
  static_assert(ggx_tables::kMu <= MsAlbedoRow::kNodes && ggx_tables::kDielMu <= MsAlbedoRow::kNodes,
                "MsAlbedoRow holds a table row");
  const float alpha = std::max(kMinGgxAlpha, m.roughness * m.roughness);
  switch (m.type) {
    case MaterialType::Emitter:
    case MaterialType::Mix:  // resolved to a component per hit (mix_material.h) before a Bsdf is built
      bxdf_ = BlackBxdf{};
      albedo_ = Vec3(0.0f);
      break;
    case MaterialType::Diffuse:
      bxdf_ = LambertBxdf{m.albedo};
      break;
    case MaterialType::Glossy:
      if (m.lobe == GlossLobe::Phong)
        bxdf_ = PhongBxdf{m.albedo, std::max(0.0f, m.exponent)};
      else
        bxdf_ = GgxReflectionBxdf::glossy(m.albedo, alpha, m.energy_compensation);
      break;
    case MaterialType::Conductor:
      albedo_ = fresnel_conductor(1.0f, m.eta, m.k);  // the albedo AOV: normal-incidence reflectance
      if (m.roughness > 0)
        bxdf_ = GgxReflectionBxdf::conductor(m.eta, m.k, alpha, m.energy_compensation);
      else
        bxdf_ = SmoothConductorBxdf{m.eta, m.k};
      break;
    case MaterialType::Mirror:
      bxdf_ = SchlickMirrorBxdf{m.albedo};
      break;
    case MaterialType::ThinDielectric:
      bxdf_ = ThinDielectricBxdf{m.albedo, m.ior};
      break;
    case MaterialType::CoatedDiffuse:
      if (m.layered)
        bxdf_ = LayeredBxdf::coated_diffuse(m);
      else
        bxdf_ = CoatedDiffuse(m);
      break;
    case MaterialType::CoatedConductor:
      albedo_ = fresnel_conductor(1.0f, m.eta, m.k);  // the albedo AOV: the bare base's normal-incidence reflectance
      bxdf_ = LayeredBxdf::coated_conductor(m);
      break;
    case MaterialType::Dielectric:
      // Index-matched: the interface is invisible, a pure pass-through (delta).
      if (m.roughness > 0 && m.ior != 1.0f)
        bxdf_ = RoughDielectricBxdf::make(m.albedo, alpha, m.ior, m.energy_compensation);
      else
        bxdf_ = SmoothDielectricBxdf{m.albedo, m.ior};
      break;
  }
}

Material regularized(const Material& m) {
  // The roughness of the regularised alpha, or the roughness itself when alpha is rough enough.
  auto roughen = [](float roughness) {
    const float alpha = roughness * roughness;
    if (alpha >= kRegularizeAlphaMax) return roughness;
    return std::sqrt(std::clamp(2.0f * alpha, kRegularizeAlphaMin, kRegularizeAlphaMax));
  };
  Material r = m;
  switch (m.type) {
    case MaterialType::Glossy:
      if (m.lobe == GlossLobe::Phong) {
        // Walter et al. 2007's equivalence alpha = sqrt(2 / (n + 2)).
        const float alpha = std::sqrt(2.0f / (std::max(0.0f, m.exponent) + 2.0f));
        if (alpha < kRegularizeAlphaMax) {
          const float a = std::clamp(2.0f * alpha, kRegularizeAlphaMin, kRegularizeAlphaMax);
          r.exponent = 2.0f / (a * a) - 2.0f;
        }
      } else {
        r.roughness = roughen(m.roughness);
      }
      break;
    case MaterialType::Conductor:
    case MaterialType::Dielectric:
    case MaterialType::CoatedDiffuse:
      r.roughness = roughen(m.roughness);
      break;
    case MaterialType::CoatedConductor:
      // pbrt-v4's LayeredBxDF::Regularize: both interfaces.
      r.roughness = roughen(m.roughness);
      r.base_roughness = roughen(m.base_roughness);
      break;
    case MaterialType::Mirror:
      r.type = MaterialType::Glossy;
      r.lobe = GlossLobe::GGX;
      r.roughness = roughen(0.0f);
      break;
    default:
      break;
  }
  return r;
}

}  // namespace pdrt
