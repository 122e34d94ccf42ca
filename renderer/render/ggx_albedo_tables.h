#pragma once
// The grids of the GGX albedo tables (ggx_albedo.h) and the arrays the build generates on them
// (renderer/tablegen/ggx_albedo_tablegen.cpp writes them into the build tree). Shared by the
// generator and the lookup, so that both agree on where the nodes are.
namespace pdrt::ggx_tables {

// Conductor: E(mu, alpha) on mu = i / (kMu - 1) and roughness sqrt(alpha) = j / (kRough - 1).
inline constexpr int kMu = 32, kRough = 32;
// Dielectric: E(mu, alpha, eta) for eta = transmitted over incident index; the grid holds
// eta_big = max(eta, 1 / eta) = 1 + (kEtaMax - 1) k / (kEta - 1), and side 0 (eta >= 1, entering
// the denser medium) or 1 (eta < 1, leaving it).
inline constexpr int kDielMu = 16, kDielRough = 16, kEta = 12;
inline constexpr float kEtaMax = 3.0f;

// The albedo at mu = 0 is taken at this cosine: at exactly 0 the lobes are undefined.
inline constexpr float kMinMu = 1e-4f;

inline constexpr float mu_node(int i, int count) { return i == 0 ? kMinMu : float(i) / float(count - 1); }
inline constexpr float rough_node(int j, int count) { return float(j) / float(count - 1); }
inline constexpr float eta_node(int k) { return 1.0f + (kEtaMax - 1.0f) * float(k) / float(kEta - 1); }

// E of white single-scattering GGX reflection and its cosine-weighted hemispherical average
// 2 int E(mu) mu dmu of the piecewise-linear interpolant (so that the compensation lobe built on
// the interpolated E integrates exactly to what it should).
extern const float kConductorAlbedo[kRough][kMu];
extern const float kConductorAverage[kRough];
// The same for the rough dielectric's reflection plus transmission, as energy (without the
// 1 / eta^2 radiance scaling), white.
extern const float kDielectricAlbedo[2][kEta][kDielRough][kDielMu];
extern const float kDielectricAverage[2][kEta][kDielRough];
// The rough dielectric's reflection alone, from outside (eta >= 1, side 0's grid), white: the
// coat of coated_diffuse.
extern const float kCoatAlbedo[kEta][kDielRough][kDielMu];
extern const float kCoatAverage[kEta][kDielRough];

}  // namespace pdrt::ggx_tables
