#pragma once
// Reflection and refraction at a smooth interface: mirror and refracted directions, exact
// dielectric Fresnel reflectance and Schlick's approximation.
#include "renderer/scene/vec3.h"

namespace pdrt {

// Mirror image of w about the unit normal n.
inline Vec3 reflect(const Vec3& w, const Vec3& n) { return n * (2.0f * dot(w, n)) - w; }

// Direction refracted through the plane with unit normal n, where w is on the side of n
// (dot(w, n) > 0) and eta = eta_transmitted / eta_incident. False under total internal reflection.
bool refract(const Vec3& w, const Vec3& n, float eta, Vec3* wt);

// Exact unpolarised Fresnel reflectance of a dielectric interface for cos_i > 0 on the incident
// side, eta = eta_transmitted / eta_incident. 1 under total internal reflection. In double: near
// the critical angle 1 - F loses all float precision (cos_t = sqrt(1 - sin_t^2)).
double fresnel_dielectric(double cos_i, double eta);

// Hemispherical cosine-weighted average 2 int_0^1 F(mu, eta) mu dmu of fresnel_dielectric.
double fresnel_dielectric_average(double eta);
// The same in closed form, for eta >= 1 (seen from the less dense side): a few logarithms
// instead of a quadrature, so cheap enough for a per-hit BSDF. From inside, by the reciprocity
// of transmission: 1 - F_avg(1 / eta) = (1 - F_avg(eta)) / eta^2.
double fresnel_dielectric_average_closed(double eta);

// Exact unpolarised Fresnel reflectance of a conductor (or any absorbing medium) with complex
// relative index eta + i k, for cos_i > 0 on the incident side (the side of index 1). The s and p
// amplitude coefficients with the complex cos_t = sqrt(1 - sin_i^2 / (eta + ik)^2), averaged in
// power (Born & Wolf §14.2; pbrt-v4's FrComplex). k = 0 is fresnel_dielectric, including total
// internal reflection for eta < 1 (cos_t becomes imaginary and |r| = 1).
double fresnel_conductor(double cos_i, double eta, double k);
// Per RGB channel.
Vec3 fresnel_conductor(float cos_i, const Vec3& eta, const Vec3& k);
// Its hemispherical cosine-weighted average 2 int_0^1 F(mu) mu dmu, per channel.
Vec3 fresnel_conductor_average(const Vec3& eta, const Vec3& k);
// Normal-incidence reflectance ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2).
double conductor_r0(double eta, double k);

// Schlick 1994: f0 + (1 - f0)(1 - cos)^5.
Vec3 fresnel_schlick(const Vec3& f0, float cos_i);

}  // namespace pdrt
