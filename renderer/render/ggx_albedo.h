#pragma once
// Directional albedo E of single-scattering GGX and its cosine-weighted average, from the tables
// the build generates (ggx_albedo_tables.h): what multiple-scattering energy compensation
// (Kulla & Conty 2017) needs. White (F = 1 for the conductor, albedo 1 for the dielectric);
// mu = |cos theta| of the direction, alpha the GGX width. Interpolated linearly in mu,
// sqrt(alpha) and eta, clamped to the grid.
namespace pdrt {

// Conductor: E(mu) = int f_ss(wo, wi) cos(wi) dwi with F = 1.
float ggx_conductor_albedo(float mu, float alpha);
// E_avg = 2 int_0^1 E(mu) mu dmu.
float ggx_conductor_albedo_average(float alpha);

// Rough dielectric seen from the side where eta = transmitted over incident index (ior from
// outside, 1 / ior from inside): reflection plus transmission, as energy (without 1 / eta^2).
float ggx_dielectric_albedo(float mu, float alpha, float eta);
float ggx_dielectric_albedo_average(float alpha, float eta);

// Reflection alone of the rough dielectric seen from outside, eta = ior >= 1 (clamped to the
// grid, [1, 3]): the albedo of the coat of coated_diffuse, white, exact Fresnel at wo.m.
float ggx_coat_albedo(float mu, float alpha, float eta);
float ggx_coat_albedo_average(float alpha, float eta);

// Number of mu nodes of the conductor (false) or dielectric and coat (true) tables: between them the
// lookups are linear in mu.
int ggx_albedo_nodes(bool dielectric);

}  // namespace pdrt
