#pragma once
// Multiple-scattering energy compensation (Material::energy_compensation, on by default):
// single-scattering GGX loses the light that bounces more than once between microfacets (31 %
// kept at roughness 1). A diffuse-like lobe built on the albedo tables of ggx_albedo.h returns
// it (Kulla & Conty 2017; ggx_reflection.h and rough_dielectric.h). This is the tables' row at
// one alpha (and eta): E(mu) per side (0: wo.z > 0, 1 below; reflection uses side 0) on the
// tables' mu nodes, so that a lookup is one lerp, and E_avg per side.
namespace pdrt {

struct MsAlbedoRow {
  static constexpr int kNodes = 32;
  float e[2][kNodes] = {};
  int nodes = kNodes;
  float e_avg[2] = {1, 1};

  // E of the single-scattering lobe at |cos| = mu on a side. The tables are linear in mu
  // between their nodes, so this equals the full lookup.
  float at(float mu, int side) const;
};

}  // namespace pdrt
