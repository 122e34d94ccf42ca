#include "renderer/render/ggx_albedo.h"

#include "renderer/render/ggx_albedo_tables.h"

#include <algorithm>
#include <cmath>

namespace pdrt {
namespace {

using namespace ggx_tables;

// Grid coordinate of x in [0, 1] over `count` equally spaced nodes: lower node and weight.
struct Lerp {
  int i;
  float t;
};
Lerp lerp_at(float x, int count) {
  float g = std::clamp(x, 0.0f, 1.0f) * float(count - 1);
  int i = std::min(int(g), count - 2);
  return {i, g - float(i)};
}

float mix(float a, float b, float t) { return a + (b - a) * t; }

// Side and eta coordinate of the dielectric tables.
struct EtaAt {
  int side;
  Lerp k;
};
EtaAt eta_at(float eta) {
  int side = eta >= 1.0f ? 0 : 1;
  float big = side == 0 ? eta : 1.0f / eta;
  return {side, lerp_at((big - 1.0f) / (kEtaMax - 1.0f), kEta)};
}

}  // namespace

float ggx_conductor_albedo(float mu, float alpha) {
  Lerp r = lerp_at(std::sqrt(alpha), kRough), m = lerp_at(mu, kMu);
  auto row = [&](int j) { return mix(kConductorAlbedo[j][m.i], kConductorAlbedo[j][m.i + 1], m.t); };
  return mix(row(r.i), row(r.i + 1), r.t);
}

float ggx_conductor_albedo_average(float alpha) {
  Lerp r = lerp_at(std::sqrt(alpha), kRough);
  return mix(kConductorAverage[r.i], kConductorAverage[r.i + 1], r.t);
}

float ggx_dielectric_albedo(float mu, float alpha, float eta) {
  EtaAt e = eta_at(eta);
  Lerp r = lerp_at(std::sqrt(alpha), kDielRough), m = lerp_at(mu, kDielMu);
  auto at = [&](int k, int j) {
    const float* v = kDielectricAlbedo[e.side][k][j];
    return mix(v[m.i], v[m.i + 1], m.t);
  };
  auto plane = [&](int k) { return mix(at(k, r.i), at(k, r.i + 1), r.t); };
  return mix(plane(e.k.i), plane(e.k.i + 1), e.k.t);
}

float ggx_coat_albedo(float mu, float alpha, float eta) {
  Lerp k = eta_at(std::max(1.0f, eta)).k;
  Lerp r = lerp_at(std::sqrt(alpha), kDielRough), m = lerp_at(mu, kDielMu);
  auto at = [&](int kk, int j) { return mix(kCoatAlbedo[kk][j][m.i], kCoatAlbedo[kk][j][m.i + 1], m.t); };
  auto plane = [&](int kk) { return mix(at(kk, r.i), at(kk, r.i + 1), r.t); };
  return mix(plane(k.i), plane(k.i + 1), k.t);
}

float ggx_coat_albedo_average(float alpha, float eta) {
  Lerp k = eta_at(std::max(1.0f, eta)).k;
  Lerp r = lerp_at(std::sqrt(alpha), kDielRough);
  auto plane = [&](int kk) { return mix(kCoatAverage[kk][r.i], kCoatAverage[kk][r.i + 1], r.t); };
  return mix(plane(k.i), plane(k.i + 1), k.t);
}

int ggx_albedo_nodes(bool dielectric) { return dielectric ? kDielMu : kMu; }

float ggx_dielectric_albedo_average(float alpha, float eta) {
  EtaAt e = eta_at(eta);
  Lerp r = lerp_at(std::sqrt(alpha), kDielRough);
  auto plane = [&](int k) {
    const float* v = kDielectricAverage[e.side][k];
    return mix(v[r.i], v[r.i + 1], r.t);
  };
  return mix(plane(e.k.i), plane(e.k.i + 1), e.k.t);
}

}  // namespace pdrt
