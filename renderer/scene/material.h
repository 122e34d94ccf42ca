#pragma once
// A material as the scene file describes it (docs/scene-format.md). The BSDF built from it
// lives in bsdf.h; emission is a property of the material, so any shape can be a light.
#include "renderer/scene/vec3.h"

#include <string>
#include <vector>

namespace pdrt {

enum class MaterialType {
  Diffuse,
  Glossy,
  Mirror,
  Dielectric,
  Emitter,
  Conductor,
  CoatedDiffuse,
  ThinDielectric,
  Mix,
  CoatedConductor
};
enum class GlossLobe { GGX, Phong };

// The material parameters a texture may drive (render/texture_set.h writes them per hit).
// Colours take the texture's RGB; scalars its first channel. A new textured parameter is one
// entry here, one case in TextureSet::apply and one textured_* call in the loader.
// Amount: a mix's probability of its second material. Reflectance: a conductor's normal-incidence
// reflectance, which sets eta = 1 and k from it (pbrt-v4's ConductorMaterial "reflectance").
// BaseRoughness: the roughness of a coated_conductor's conductor under its coat.
enum class MaterialParam { Albedo, Roughness, CoatColor, Radiance, Amount, Reflectance, BaseRoughness };
struct TextureBinding {
  MaterialParam param;
  int texture;  // index into SceneDesc::textures
  bool operator==(const TextureBinding&) const = default;
};

// The slab between a layered material's coat and base (pbrt-v4's LayeredBxDF parameters and
// defaults, render/bxdf/layered.h): coated_diffuse with "model": "layered", and coated_conductor.
struct CoatLayers {
  float thickness = 0.01f;  // of the medium, whose extinction is 1 per unit: exp(-thickness / |cos|) a crossing
  Vec3 albedo{0.0f};        // the medium's single-scattering albedo; black: it only absorbs
  float g = 0.0f;           // Henyey-Greenstein asymmetry of the medium's phase function
  int max_depth = 10;       // events of one random walk
  int samples = 1;          // random walks per evaluation
  // f()'s exit weighted consistently (LayeredBxdf::ExitMis::Consistent) instead of as pbrt-v4
  // does; for tests that measure the difference, not in the scene format.
  bool consistent_exit = false;
};

struct Material {
  std::string name;
  MaterialType type = MaterialType::Diffuse;
  Vec3 albedo{
      0.8f};  // diffuse (and coated_diffuse base) reflectance; glossy/mirror F0 (Schlick); dielectric transmission tint
  GlossLobe lobe = GlossLobe::GGX;
  float roughness = 0.0f;       // perceptual: GGX alpha = roughness^2; 0 = smooth (delta); coated_diffuse: the coat's
  float exponent = 0.0f;        // normalised Phong exponent (lobe == Phong)
  float ior = 1.5f;             // dielectric and coated_diffuse's coat, relative to the outside medium
  Vec3 eta{1.0f};               // conductor: real part of the complex index per RGB channel (> 0)
  Vec3 k{0.0f};                 // conductor: imaginary part (extinction) per RGB channel (>= 0)
  Vec3 coat_color{1.0f};        // coated_diffuse: coat transmittance of one pass at normal incidence (thickness 1)
  float coat_thickness = 1.0f;  // coated_diffuse: scales the coat's optical depth, >= 0
  // coated_diffuse: pbrt-v4's stochastic layered model (the slab `layers`) instead of the
  // analytic one (coat_color, coat_thickness); coated_conductor is always layered.
  bool layered = false;
  CoatLayers layers;
  float base_roughness = 0.0f;  // coated_conductor: the conductor's roughness under the coat (eta, k: its index)
  Vec3 radiance{0.0f};          // emitted radiance (Emitter)
  bool two_sided = false;       // emitters: emit from both faces (default: front face only)
  bool energy_compensation =
      true;  // GGX glossy, rough conductor and rough dielectric: add the multiple-scattering lobe
  std::vector<TextureBinding> textures;  // parameters given by a texture (empty: constant material)
  // Mix: its two materials (indices into SceneDesc::materials, never emitters) and the
  // probability of choosing mix[1] at a hit (render/mix_material.h).
  int mix[2] = {-1, -1};
  float amount = 0.5f;
};

// A conductor of normal-incidence reflectance r (per channel, clamped below 1): eta = 1 and
// k = 2 sqrt(r) / sqrt(1 - r), as pbrt-v4's ConductorMaterial does with "reflectance".
void conductor_from_reflectance(const Vec3& r, Material* m);

// Measured complex indices of named metals at 650, 550 and 450 nm (R, G, B): material.cpp.
struct NamedMetal {
  const char* name;
  Vec3 eta, k;
};
const NamedMetal* find_named_metal(const std::string& name);  // nullptr if unknown
std::string named_metal_list();                               // "\"Ag\", \"Al\", \"Au\", \"Cu\""

}  // namespace pdrt
