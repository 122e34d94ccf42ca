// The GGX albedo tables the build generates (renderer/tablegen/ggx_albedo_tablegen.cpp, read
// through renderer/render/ggx_albedo.h) against brute-force integrals of the uncompensated
// BSDF's eval() over the sphere: a different method (direction quadrature, not the
// generator's visible-normal sampling) at points on and between the grid nodes.
#include "renderer/render/ggx_albedo.h"
#include "tests/support/sphere_quadrature.h"

#include <gtest/gtest.h>

namespace pdrt {
namespace {

Vec3 wo_at(float mu) { return {std::sqrt(1 - mu * mu), 0, mu}; }

Material uncompensated(MaterialType type, float roughness, float ior = 1.5f) {
  Material m;
  m.type = type;
  m.roughness = roughness;
  m.ior = ior;
  m.albedo = Vec3(1.0f);
  m.energy_compensation = false;
  return m;
}

// Absolute tolerance: the generator's 64^2 (conductor) and 40^2 (dielectric) midpoint rules
// and linear interpolation between nodes; the quadrature here is good to ~1e-4.
TEST(GgxAlbedo, ConductorTableMatchesBruteForce) {
  struct P {
    float mu, roughness;
  };
  for (P p : {P{1.0f, 1.0f}, P{0.5f, 0.5f}, P{0.2f, 0.8f}, P{0.75f, 0.3f}, P{0.9f, 0.65f}}) {
    float alpha = p.roughness * p.roughness;
    double ref = test::energy_albedo(Bsdf(uncompensated(MaterialType::Glossy, p.roughness)), wo_at(p.mu));
    EXPECT_NEAR(ggx_conductor_albedo(p.mu, alpha), ref, 3e-3) << "mu " << p.mu << " roughness " << p.roughness;
  }
}

TEST(GgxAlbedo, DielectricTableMatchesBruteForceFromBothSides) {
  struct P {
    float mu, roughness, ior;
    bool inside;
  };
  for (P p : {P{1.0f, 0.8f, 1.5f, false}, P{0.5f, 0.5f, 1.5f, false}, P{0.7f, 0.8f, 1.5f, true},
              P{0.3f, 0.6f, 1.33f, true}, P{0.9f, 1.0f, 2.4f, false}}) {
    float alpha = p.roughness * p.roughness;
    Vec3 wo = wo_at(p.mu);
    if (p.inside) wo.z = -wo.z;
    double ref = test::energy_albedo(Bsdf(uncompensated(MaterialType::Dielectric, p.roughness, p.ior)), wo, p.ior);
    float eta = p.inside ? 1.0f / p.ior : p.ior;
    EXPECT_NEAR(ggx_dielectric_albedo(p.mu, alpha, eta), ref, 5e-3)
        << "mu " << p.mu << " roughness " << p.roughness << " ior " << p.ior << " inside " << p.inside;
  }
}

// The coat of coated_diffuse: the rough dielectric's reflection alone, from outside. A black
// base leaves only the coat lobe in eval().
TEST(GgxAlbedo, CoatTableMatchesBruteForce) {
  struct P {
    float mu, roughness, ior;
  };
  for (P p :
       {P{1.0f, 0.8f, 1.5f}, P{0.5f, 0.5f, 1.5f}, P{0.2f, 0.3f, 1.33f}, P{0.1f, 0.7f, 2.4f}, P{0.7f, 1.0f, 3.0f}}) {
    Material m;
    m.type = MaterialType::CoatedDiffuse;
    m.roughness = p.roughness, m.ior = p.ior, m.albedo = Vec3(0.0f);
    double ref = test::energy_albedo(Bsdf(m), wo_at(p.mu));
    EXPECT_NEAR(ggx_coat_albedo(p.mu, p.roughness * p.roughness, p.ior), ref, 3e-3)
        << "mu " << p.mu << " roughness " << p.roughness << " ior " << p.ior;
  }
}

// The average is 2 int E mu dmu of the same interpolated E the lookup returns.
TEST(GgxAlbedo, AverageIsTheCosineWeightedMeanOfTheLookup) {
  for (float r : {0.3f, 0.7f, 1.0f}) {
    const int n = 20000;
    double c = 0, d = 0, e = 0;
    for (int i = 0; i < n; ++i) {
      float mu = (i + 0.5f) / n;
      c += ggx_conductor_albedo(mu, r * r) * mu, d += ggx_dielectric_albedo(mu, r * r, 1 / 1.5f) * mu;
      e += ggx_coat_albedo(mu, r * r, 1.7f) * mu;
    }
    EXPECT_NEAR(ggx_conductor_albedo_average(r * r), 2 * c / n, 1e-5) << "roughness " << r;
    EXPECT_NEAR(ggx_dielectric_albedo_average(r * r, 1 / 1.5f), 2 * d / n, 1e-5) << "roughness " << r;
    EXPECT_NEAR(ggx_coat_albedo_average(r * r, 1.7f), 2 * e / n, 1e-5) << "roughness " << r;
  }
}

}  // namespace
}  // namespace pdrt
