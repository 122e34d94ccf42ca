// BSDFs: sampling matches pdf (chi-square), weights match eval, energy, reciprocity, Fresnel.
#include "renderer/render/bsdf.h"
#include "renderer/render/fresnel.h"
#include "renderer/render/microfacet_ggx.h"
#include "sampling/core/rng.h"
#include "tests/support/bsdf_chi_square.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace pdrt {
namespace {

using namespace pdrt::test;

Vec3 direction(float theta_deg, float phi = 0.7f) {
  float t = theta_deg * kPi / 180.0f;
  return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

Vec3 uniform_sphere(Rng& rng) {
  double z = 1.0 - 2.0 * rng.uniform(), phi = 2.0 * M_PI * rng.uniform();
  double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)};
}

Material diffuse(Vec3 albedo) {
  Material m;
  m.type = MaterialType::Diffuse;
  m.albedo = albedo;
  return m;
}

Material ggx(float roughness, Vec3 albedo = Vec3(1.0f)) {
  Material m;
  m.type = MaterialType::Glossy;
  m.lobe = GlossLobe::GGX;
  m.roughness = roughness;
  m.albedo = albedo;
  return m;
}

Material phong(float exponent, Vec3 albedo = Vec3(1.0f)) {
  Material m;
  m.type = MaterialType::Glossy;
  m.lobe = GlossLobe::Phong;
  m.exponent = exponent;
  m.albedo = albedo;
  return m;
}

Material dielectric(float roughness, float ior = 1.5f, Vec3 albedo = Vec3(1.0f)) {
  Material m;
  m.type = MaterialType::Dielectric;
  m.roughness = roughness;
  m.ior = ior;
  m.albedo = albedo;
  return m;
}

Material mirror(Vec3 albedo) {
  Material m;
  m.type = MaterialType::Mirror;
  m.albedo = albedo;
  return m;
}

Material conductor(float roughness, Vec3 eta, Vec3 k) {
  Material m;
  m.type = MaterialType::Conductor;
  m.roughness = roughness;
  m.eta = eta;
  m.k = k;
  return m;
}

Material metal(const char* name, float roughness) {
  const NamedMetal* nm = find_named_metal(name);
  return conductor(roughness, nm->eta, nm->k);
}

struct FitCase {
  std::string name;
  Material material;
  Vec3 wo;
};

std::vector<FitCase> fit_cases() {
  std::vector<FitCase> cases;
  for (float t : {0.0f, 45.0f, 80.0f})
    cases.push_back({"Diffuse_theta" + std::to_string(int(t)), diffuse(Vec3(0.5f)), direction(t)});
  for (int r : {2, 5, 9})
    for (float t : {0.0f, 30.0f, 60.0f, 80.0f})
      cases.push_back(
          {"Ggx_r0p" + std::to_string(r) + "_theta" + std::to_string(int(t)), ggx(0.1f * r, Vec3(0.7f)), direction(t)});
  for (float n : {10.0f, 100.0f})
    for (float t : {0.0f, 45.0f, 80.0f})
      cases.push_back({"Phong_n" + std::to_string(int(n)) + "_theta" + std::to_string(int(t)), phong(n), direction(t)});
  for (int r : {3, 7}) {
    for (float t : {20.0f, 70.0f})
      cases.push_back({"RoughDielectric_r0p" + std::to_string(r) + "_outside_theta" + std::to_string(int(t)),
                       dielectric(0.1f * r), direction(t)});
    // From inside (ior 1.5: critical angle 41.8 deg): one below, one beyond the critical angle.
    for (float t : {20.0f, 60.0f})
      cases.push_back({"RoughDielectric_r0p" + std::to_string(r) + "_inside_theta" + std::to_string(int(t)),
                       dielectric(0.1f * r), -direction(t)});
  }
  // Rough conductors: the GGX lobe with the exact complex Fresnel (gold, plus compensation lobe).
  for (int r : {2, 6})
    for (float t : {0.0f, 45.0f, 80.0f})
      cases.push_back({"ConductorAu_r0p" + std::to_string(r) + "_theta" + std::to_string(int(t)), metal("Au", 0.1f * r),
                       direction(t)});
  return cases;
}

void PrintTo(const FitCase& c, std::ostream* os) { *os << c.name; }

class SampleMatchesPdf : public ::testing::TestWithParam<FitCase> {};

TEST_P(SampleMatchesPdf, ChiSquareAndTotalProbability) {
  const FitCase& c = GetParam();
  Bsdf bsdf(c.material);
  const int64_t n = 500000;
  uint64_t seed = 1234;  // from the case name, not std::hash: the same on every standard library
  for (char ch : c.name) seed = hash_combine(seed, uint64_t(ch));
  FitResult r = chi_square_fit(bsdf, c.wo, seed, n);
  // Significance 0.01 for the whole family, Sidak-corrected over its cases.
  const double alpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / double(fit_cases().size()));
  EXPECT_GT(r.p, alpha) << "chi2 = " << r.statistic << " dof = " << r.dof;
  EXPECT_EQ(r.zero_pdf_samples, 0);
  EXPECT_EQ(r.pdf_mismatches, 0);
  // pdf() integrates to the probability that sample() succeeds: 4 binomial sigma, plus 1e-4
  // for the quadrature (its tolerance sums to 8e-5 over the sphere).
  double s = r.success_fraction;
  EXPECT_NEAR(r.pdf_integral, s, 4.0 * std::sqrt(s * (1 - s) / double(n)) + 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Bsdf, SampleMatchesPdf, ::testing::ValuesIn(fit_cases()),
                         [](const ::testing::TestParamInfo<FitCase>& info) { return info.param.name; });

// ---- Weights and pdfs reported by sample() agree with eval() and pdf().

TEST(Bsdf, SampleWeightIsEvalCosOverPdf) {
  std::vector<Material> materials = {diffuse(Vec3(0.2f, 0.5f, 0.9f)),
                                     ggx(0.2f, Vec3(0.9f, 0.5f, 0.1f)),
                                     ggx(0.5f),
                                     ggx(0.9f, Vec3(0.3f)),
                                     phong(10),
                                     phong(100, Vec3(0.5f, 0.6f, 0.7f)),
                                     dielectric(0.3f, 1.5f, Vec3(0.9f, 0.8f, 0.7f)),
                                     dielectric(0.7f, 1.33f)};
  Rng rng(77);
  for (const Material& m : materials) {
    Bsdf bsdf(m);
    for (float t : {0.0f, 30.0f, 60.0f, 80.0f, 89.0f}) {
      for (Vec3 wo : {direction(t, 0.3f), -direction(t, 1.9f)}) {
        if (m.type != MaterialType::Dielectric && wo.z < 0) continue;
        for (int i = 0; i < 2000; ++i) {
          BsdfSample s;
          if (!bsdf.sample(wo, uniform_float(rng), uniform_float(rng), uniform_float(rng), &s)) continue;
          ASSERT_FALSE(s.delta);
          ASSERT_NEAR(length(s.wi), 1.0f, 1e-5f);
          ASSERT_EQ(s.transmission, (s.wi.z < 0) != (wo.z < 0));
          float p = bsdf.pdf(wo, s.wi);
          ASSERT_LE(rel_diff(p, s.pdf), 1e-3) << "theta " << t;
          Vec3 expect = bsdf.eval(wo, s.wi) * (std::abs(s.wi.z) / p);
          for (int k = 0; k < 3; ++k) ASSERT_LE(rel_diff(s.weight[k], expect[k]), 1e-3) << "theta " << t << " k " << k;
        }
      }
    }
  }
}

// ---- Microfacet distribution identities (numerical quadrature over the hemisphere).

// Integral of f(direction) over the upper hemisphere, in (theta, phi) like the chi-square bins.
template <class F>
double integrate_hemisphere(F f) {
  auto g = [&](double theta, double phi) { return f(from_theta_phi(theta, phi)) * std::sin(theta); };
  double sum = 0;
  const int nt = 16, np = 16;
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      double x0 = 0.5 * M_PI * i / nt, x1 = 0.5 * M_PI * (i + 1) / nt, y0 = 2 * M_PI * j / np,
             y1 = 2 * M_PI * (j + 1) / np;
      sum += adaptive_simpson(g, x0, x1, y0, y1, simpson3x3(g, x0, x1, y0, y1), 1e-9, 1e-6, 8);
    }
  return sum;
}

TEST(MicrofacetGgx, ProjectedNormalAreaIsOne) {
  // Walter 2007 eq. 4: the projected microfacet area equals the macro area. Quadrature to 1e-4.
  for (float a : {0.1f, 0.3f, 0.7f, 1.0f}) {
    MicrofacetGgx d(a);
    EXPECT_NEAR(integrate_hemisphere([&](const Vec3& m) { return d.d(m) * m.z; }), 1.0, 1e-4) << "alpha " << a;
  }
}

TEST(MicrofacetGgx, VisibleNormalsIntegrateToOne) {
  // Heitz 2014 eq. 17: with Smith's G1, the visible projected area equals wo.z. Quadrature to 1e-4.
  for (float a : {0.1f, 0.4f, 1.0f})
    for (float t : {0.0f, 45.0f, 80.0f}) {
      MicrofacetGgx d(a);
      Vec3 w = direction(t);
      EXPECT_NEAR(integrate_hemisphere([&](const Vec3& m) { return d.pdf_visible(w, m); }), 1.0, 1e-4)
          << "alpha " << a << " theta " << t;
    }
}

TEST(MicrofacetGgx, HeightCorrelatedMaskingIsBelowUncorrelatedAndAboveZero) {
  // G1(o) G1(i) <= G2(o, i) <= min(G1(o), G1(i)) (Heitz 2014 §6).
  MicrofacetGgx d(0.5f);
  for (float to : {0.0f, 40.0f, 85.0f})
    for (float ti : {10.0f, 60.0f, 89.0f}) {
      Vec3 o = direction(to), i = direction(ti, 2.0f);
      float g2 = d.g2(o, i);
      EXPECT_GE(g2, d.g1(o) * d.g1(i) * (1 - 1e-6f));
      EXPECT_LE(g2, std::min(d.g1(o), d.g1(i)) * (1 + 1e-6f));
    }
}

// ---- Energy.

struct Estimate {
  double mean, sigma;  // per channel 0 (all tests use grey albedo)
};

Estimate mean_weight(const Bsdf& bsdf, const Vec3& wo, uint64_t seed, int n, bool remove_eta2 = false, float ior = 1) {
  Rng rng(seed);
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    BsdfSample s;
    double w = 0;
    if (bsdf.sample(wo, uniform_float(rng), uniform_float(rng), uniform_float(rng), &s)) {
      w = s.weight.x;
      if (remove_eta2 && s.transmission) {
        double eta = wo.z > 0 ? ior : 1.0 / ior;
        w *= eta * eta;
      }
    }
    sum += w, sum2 += w * w;
  }
  double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

TEST(Bsdf, GlossyGgxNeverCreatesEnergy) {
  // White furnace: mean of weights (failed samples count 0) <= 1 + 3 sigma; with energy
  // compensation + 3e-3, the albedo tables' accuracy (tests/renderer/render/test_ggx_albedo.cpp).
  for (bool comp : {false, true})
    for (float r : {0.05f, 0.2f, 0.5f, 0.9f, 1.0f})
      for (float t : {0.0f, 45.0f, 70.0f, 85.0f, 89.5f}) {
        Material m = ggx(r);
        m.energy_compensation = comp;
        Estimate e = mean_weight(Bsdf(m), direction(t), 11, 50000);
        EXPECT_LE(e.mean, 1.0 + 3.0 * e.sigma + (comp ? 3e-3 : 0.0))
            << "roughness " << r << " theta " << t << " comp " << comp;
      }
}

TEST(Bsdf, SmoothGgxAtNormalIncidenceLosesAlmostNothing) {
  // Single-scattering GGX at alpha = 0.04 loses well under 0.5 % at normal incidence (with
  // multiple-scattering compensation off); a wrong D, G or Jacobian would show here.
  Material m = ggx(0.2f);
  m.energy_compensation = false;
  Estimate e = mean_weight(Bsdf(m), direction(0), 12, 50000);
  EXPECT_GT(e.mean, 0.995);
  EXPECT_LE(e.mean, 1.0);
}

TEST(Bsdf, GlossyPhongNeverCreatesEnergy) {
  for (float n : {0.0f, 1.0f, 10.0f, 100.0f, 1000.0f})
    for (float t : {0.0f, 45.0f, 70.0f, 85.0f, 89.5f}) {
      Estimate e = mean_weight(Bsdf(phong(n)), direction(t), 13, 50000);
      EXPECT_LE(e.mean, 1.0 + 3.0 * e.sigma) << "exponent " << n << " theta " << t;
    }
}

TEST(Bsdf, PhongAtNormalIncidenceReflectsAlbedo) {
  // The (n+2)/(2 pi) normalisation makes the lobe about the normal integrate to exactly albedo.
  for (float n : {1.0f, 10.0f, 100.0f}) {
    Estimate e = mean_weight(Bsdf(phong(n, Vec3(0.6f))), direction(0), 14, 100000);
    EXPECT_NEAR(e.mean, 0.6, 4.0 * e.sigma + 1e-6) << "exponent " << n;
  }
}

TEST(Bsdf, DiffuseReflectsExactlyItsAlbedo) {
  // Two estimates within 0.5 %: the sampled weights, and eval() integrated by uniform hemisphere
  // sampling (sigma ~ 0.06 % at 1e6 samples, so 0.5 % is > 8 sigma).
  Vec3 albedo{0.2f, 0.5f, 0.9f};
  Bsdf bsdf(diffuse(albedo));
  Rng rng(5);
  for (float t : {0.0f, 50.0f, 85.0f}) {
    Vec3 wo = direction(t);
    double sampled[3] = {0, 0, 0}, uniform[3] = {0, 0, 0};
    const int n = 1000000;
    for (int i = 0; i < n; ++i) {
      BsdfSample s;
      if (bsdf.sample(wo, uniform_float(rng), uniform_float(rng), uniform_float(rng), &s))
        for (int k = 0; k < 3; ++k) sampled[k] += s.weight[k];
      Vec3 wi = uniform_sphere(rng);
      Vec3 f = bsdf.eval(wo, wi) * (std::abs(wi.z) * 4 * kPi);
      for (int k = 0; k < 3; ++k) uniform[k] += f[k];
    }
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(sampled[k] / n, albedo[k], 0.005 * albedo[k]);
      EXPECT_NEAR(uniform[k] / n, albedo[k], 0.005 * albedo[k]);
    }
  }
}

TEST(Bsdf, SmoothDielectricConservesEnergy) {
  // White glass: R + T with the 1/eta^2 radiance scaling undone is 1; both sides, incl. TIR.
  for (float t : {0.0f, 30.0f, 60.0f, 85.0f}) {
    for (Vec3 wo : {direction(t), -direction(t)}) {
      Estimate e = mean_weight(Bsdf(dielectric(0.0f)), wo, 21, 100000, true, 1.5f);
      EXPECT_NEAR(e.mean, 1.0, 1e-3) << "theta " << t << " z " << wo.z;
    }
  }
}

TEST(Bsdf, SmoothDielectricChoosesReflectionWithFresnelProbability) {
  // The fraction of reflected samples is F: binomial, 4 sigma.
  Bsdf bsdf(dielectric(0.0f));
  Rng rng(22);
  for (float t : {0.0f, 45.0f, 75.0f, 88.0f}) {
    for (Vec3 wo : {direction(t), -direction(t * 0.45f)}) {
      double f = fresnel_dielectric(std::abs(wo.z), wo.z > 0 ? 1.5f : 1.0f / 1.5f);
      const int n = 100000;
      int reflected = 0;
      for (int i = 0; i < n; ++i) {
        BsdfSample s;
        ASSERT_TRUE(bsdf.sample(wo, 0.5f, 0.5f, uniform_float(rng), &s));
        reflected += !s.transmission;
        ASSERT_FLOAT_EQ(s.pdf, s.transmission ? 1 - f : f);
      }
      EXPECT_NEAR(double(reflected) / n, f, 4.0 * std::sqrt(f * (1 - f) / n) + 1e-9) << "theta " << t;
    }
  }
}

TEST(Bsdf, RoughDielectricNeverCreatesEnergy) {
  // As for GGX: with compensation up to the tables' accuracy above 1 + 3 sigma.
  for (bool comp : {false, true})
    for (float r : {0.1f, 0.3f, 0.7f, 1.0f})
      for (float t : {0.0f, 45.0f, 80.0f})
        for (Vec3 wo : {direction(t), -direction(t)}) {
          Material m = dielectric(r);
          m.energy_compensation = comp;
          Estimate e = mean_weight(Bsdf(m), wo, 23, 50000, true, 1.5f);
          EXPECT_LE(e.mean, 1.0 + 3.0 * e.sigma + (comp ? 3e-3 : 0.0))
              << "roughness " << r << " theta " << t << " z " << wo.z << " comp " << comp;
        }
}

TEST(Bsdf, WhiteMirrorReturnsWeightOne) {
  Bsdf bsdf(mirror(Vec3(1.0f)));
  for (float t : {0.0f, 30.0f, 60.0f, 89.0f}) {
    BsdfSample s;
    Vec3 wo = direction(t);
    ASSERT_TRUE(bsdf.sample(wo, 0.3f, 0.6f, 0.9f, &s));
    EXPECT_TRUE(s.delta);
    EXPECT_EQ(s.pdf, 1.0f);
    EXPECT_EQ(s.weight.x, 1.0f);
    EXPECT_EQ(s.weight.y, 1.0f);
    EXPECT_EQ(s.weight.z, 1.0f);
    EXPECT_NEAR(s.wi.x, -wo.x, 1e-7f);
    EXPECT_NEAR(s.wi.y, -wo.y, 1e-7f);
    EXPECT_EQ(s.wi.z, wo.z);
  }
}

TEST(Bsdf, MirrorWeightIsSchlickFresnel) {
  Bsdf bsdf(mirror(Vec3(0.5f, 0.2f, 0.9f)));
  BsdfSample s;
  ASSERT_TRUE(bsdf.sample(direction(0), 0, 0, 0, &s));
  EXPECT_NEAR(s.weight.y, 0.2f, 1e-6f);
  ASSERT_TRUE(bsdf.sample(direction(60), 0, 0, 0, &s));
  EXPECT_NEAR(s.weight.y, 0.2f + 0.8f * std::pow(0.5f, 5.0f), 1e-6f);
}

// ---- Reciprocity.

TEST(Bsdf, ReflectionIsReciprocal) {
  std::vector<Material> materials = {diffuse(Vec3(0.5f)), ggx(0.2f, Vec3(0.3f)), ggx(0.5f),       ggx(0.9f), phong(10),
                                     phong(100),          dielectric(0.3f),      dielectric(0.7f)};
  Rng rng(31);
  for (const Material& m : materials) {
    Bsdf bsdf(m);
    int nonzero = 0;
    for (int i = 0; i < 20000; ++i) {
      Vec3 wo = uniform_sphere(rng), wi = uniform_sphere(rng);
      if (m.type == MaterialType::Dielectric) {
        if ((wo.z > 0) != (wi.z > 0)) wi.z = -wi.z;  // reflection lobe only
      } else {
        wo.z = std::abs(wo.z), wi.z = std::abs(wi.z);
      }
      // Phong n = 100 against the mirror direction of wo, so most pairs test a nonzero value.
      if (m.lobe == GlossLobe::Phong && m.type == MaterialType::Glossy && i % 2)
        wi = normalize(Vec3{-wo.x, -wo.y, wo.z} + 0.1f * uniform_sphere(rng)), wi.z = std::abs(wi.z);
      Vec3 a = bsdf.eval(wo, wi), b = bsdf.eval(wi, wo);
      if (a.x < 1e-12f && b.x < 1e-12f) continue;
      ++nonzero;
      ASSERT_LE(rel_diff(a.x, b.x), 1e-4) << "wo " << wo.x << "," << wo.y << "," << wo.z;
    }
    EXPECT_GT(nonzero, 1000);
  }
}

TEST(Bsdf, RoughDielectricTransmissionIsReciprocalUpToEta2) {
  // Radiance transport: f(wo outside -> wi inside) * ior^2 = f(wi inside -> wo outside)
  // (Veach 1997 §5.2, non-symmetric BTDF). Relative 1e-4. With and without the
  // multiple-scattering compensation lobe, whose split between reflection and transmission
  // is chosen to keep this; ior < 1 (a bubble) too.
  for (float ior : {1.5f, 1.33f, 2.4f, 0.75f})
    for (bool comp : {true, false})
      for (float r : {0.3f, 0.7f, 1.0f}) {
        Material m = dielectric(r, ior);
        m.energy_compensation = comp;
        Bsdf bsdf(m);
        Rng rng(32);
        int nonzero = 0;
        for (int i = 0; i < 20000; ++i) {
          Vec3 wo = uniform_sphere(rng), wi = uniform_sphere(rng);
          wo.z = std::abs(wo.z), wi.z = -std::abs(wi.z);
          Vec3 a = bsdf.eval(wo, wi), b = bsdf.eval(wi, wo);
          if (a.x < 1e-12f && b.x < 1e-12f) continue;
          ++nonzero;
          ASSERT_LE(rel_diff(a.x * ior * ior, b.x), 1e-4)
              << "ior " << ior << " comp " << comp << " r " << r << " wo " << wo.x << "," << wo.y << "," << wo.z
              << " wi " << wi.x << "," << wi.y << "," << wi.z << " f " << a.x << " " << b.x;
        }
        EXPECT_GT(nonzero, 1000);
      }
}

// ---- Smooth dielectric optics.

TEST(Bsdf, SmoothDielectricFresnelAtNormalIncidence) {
  for (float n : {1.33f, 1.5f, 2.4f}) {
    Bsdf bsdf(dielectric(0.0f, n));
    double f0 = ((n - 1.0) / (n + 1.0)) * ((n - 1.0) / (n + 1.0));
    for (Vec3 wo : {Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
      BsdfSample s;
      ASSERT_TRUE(bsdf.sample(wo, 0.5f, 0.5f, 0.0f, &s));
      EXPECT_FALSE(s.transmission);
      EXPECT_NEAR(s.pdf, f0, 1e-6);
      EXPECT_EQ(s.wi.z, wo.z);
      ASSERT_TRUE(bsdf.sample(wo, 0.5f, 0.5f, 0.999f, &s));
      EXPECT_TRUE(s.transmission);
      EXPECT_NEAR(s.pdf, 1.0 - f0, 1e-6);
      EXPECT_EQ(s.wi.z, -wo.z);
    }
  }
}

TEST(Fresnel, BrewsterAngleReflectsOnlyTheSPolarisation) {
  // At tan(theta) = eta, r_p = 0 and r_s = (1 - eta^2) / (1 + eta^2), so F = r_s^2 / 2.
  for (double eta : {1.33, 1.5, 2.4}) {
    double rs = (1 - eta * eta) / (1 + eta * eta);
    EXPECT_NEAR(fresnel_dielectric(1.0 / std::sqrt(1 + eta * eta), eta), 0.5 * rs * rs, 1e-12) << "eta " << eta;
  }
}

TEST(Fresnel, SameReflectanceFromBothSides) {
  // Stokes relations: F(theta_i, eta) = F(theta_t, 1 / eta) for Snell-related angles.
  for (double eta : {1.33, 1.5, 2.4})
    for (double ti : {0.0, 0.3, 0.8, 1.2, 1.5}) {
      double tt = std::asin(std::sin(ti) / eta);
      EXPECT_NEAR(fresnel_dielectric(std::cos(ti), eta), fresnel_dielectric(std::cos(tt), 1.0 / eta), 1e-12);
    }
  EXPECT_EQ(fresnel_dielectric(std::cos(0.8), 1.0 / 1.5), 1.0);  // beyond the critical angle (0.73)
}

TEST(Bsdf, SmoothDielectricTotalInternalReflectionBeyondCriticalAngle) {
  Bsdf bsdf(dielectric(0.0f, 1.5f));
  float critical = std::asin(1.0f / 1.5f) * 180.0f / kPi;  // 41.81 deg
  for (float t : {critical + 0.05f, 50.0f, 70.0f, 89.0f}) {
    Vec3 wo = -direction(t);
    BsdfSample s;
    ASSERT_TRUE(bsdf.sample(wo, 0.5f, 0.5f, 0.99999f, &s));
    EXPECT_FALSE(s.transmission) << "theta " << t;
    EXPECT_EQ(s.pdf, 1.0f);
    EXPECT_EQ(s.weight.x, 1.0f);
    EXPECT_LT(s.wi.z, 0.0f);
  }
  // Just inside the critical angle some light still leaves.
  BsdfSample s;
  ASSERT_TRUE(bsdf.sample(-direction(critical - 0.5f), 0.5f, 0.5f, 0.99999f, &s));
  EXPECT_TRUE(s.transmission);
  EXPECT_GT(s.wi.z, 0.0f);
}

TEST(Bsdf, SmoothDielectricRefractionObeysSnell) {
  const float ior = 1.5f;
  Vec3 tint{0.9f, 0.8f, 0.7f};
  Bsdf bsdf(dielectric(0.0f, ior, tint));
  for (float t : {5.0f, 30.0f, 60.0f, 85.0f}) {
    for (bool inside : {false, true}) {
      float ti = inside ? t * 0.45f : t;  // stay below the critical angle inside
      Vec3 wo = inside ? -direction(ti) : direction(ti);
      float eta = inside ? 1.0f / ior : ior;
      BsdfSample s;
      ASSERT_TRUE(bsdf.sample(wo, 0.5f, 0.5f, 0.99999f, &s));
      ASSERT_TRUE(s.transmission);
      EXPECT_TRUE(s.delta);
      EXPECT_NEAR(length(s.wi), 1.0f, 1e-6f);
      float sin_o = std::sqrt(wo.x * wo.x + wo.y * wo.y), sin_i = std::sqrt(s.wi.x * s.wi.x + s.wi.y * s.wi.y);
      EXPECT_NEAR(sin_o, eta * sin_i, 1e-6f) << "theta " << ti << " inside " << inside;
      // Opposite side, opposite azimuth: wi is wo continued through the surface.
      EXPECT_LT(s.wi.z * wo.z, 0.0f);
      EXPECT_NEAR(s.wi.x * wo.y - s.wi.y * wo.x, 0.0f, 1e-6f);
      EXPECT_LE(s.wi.x * wo.x + s.wi.y * wo.y, 0.0f);
      // Tinted and scaled by 1/eta^2 for radiance.
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.weight[k], tint[k] / (eta * eta), 1e-6f);
    }
  }
}

// ---- Degenerate inputs and the emitter.

TEST(Bsdf, SamplesAreFiniteAtTheCornersOfTheUnitSquare) {
  const float one_minus = 0x1.fffffep-1f;
  std::vector<Material> materials = {
      diffuse(Vec3(0.5f)), ggx(0.0f),          ggx(0.2f),        ggx(1.0f),          phong(0),
      phong(1000),         mirror(Vec3(0.9f)), dielectric(0.0f), dielectric(0.001f), dielectric(1.0f)};
  for (const Material& m : materials) {
    Bsdf bsdf(m);
    for (float t : {0.0f, 45.0f, 89.9f})
      for (float z : {1.0f, -1.0f})
        for (float u1 : {0.0f, 0.5f, one_minus})
          for (float u2 : {0.0f, 0.5f, one_minus})
            for (float uc : {0.0f, one_minus}) {
              Vec3 wo = direction(t) * Vec3(1, 1, z);
              BsdfSample s;
              if (!bsdf.sample(wo, u1, u2, uc, &s)) continue;
              ASSERT_TRUE(is_finite(s.wi) && is_finite(s.weight) && std::isfinite(s.pdf));
              ASSERT_GT(s.pdf, 0.0f);
              ASSERT_NEAR(length(s.wi), 1.0f, 1e-5f);
              ASSERT_TRUE(is_finite(bsdf.eval(wo, s.wi)) && std::isfinite(bsdf.pdf(wo, s.wi)));
            }
  }
}

TEST(Bsdf, OpaqueMaterialsIgnoreDirectionsBelowTheSurface) {
  for (const Material& m : {diffuse(Vec3(0.5f)), ggx(0.5f), phong(10), mirror(Vec3(1.0f))}) {
    Bsdf bsdf(m);
    Vec3 up = direction(30), down = -direction(40);
    BsdfSample s;
    EXPECT_FALSE(bsdf.sample(down, 0.3f, 0.4f, 0.5f, &s));
    EXPECT_TRUE(is_black(bsdf.eval(down, up)));
    EXPECT_TRUE(is_black(bsdf.eval(up, down)));
    EXPECT_EQ(bsdf.pdf(up, down), 0.0f);
    EXPECT_EQ(bsdf.pdf(down, up), 0.0f);
  }
}

TEST(Bsdf, EmitterIsBlackAndDoesNotScatter) {
  Material m;
  m.type = MaterialType::Emitter;
  m.radiance = Vec3(5.0f);
  Bsdf bsdf(m);
  BsdfSample s;
  EXPECT_FALSE(bsdf.scatters());
  EXPECT_FALSE(bsdf.sample(direction(10), 0.3f, 0.4f, 0.5f, &s));
  EXPECT_TRUE(is_black(bsdf.eval(direction(10), direction(20))));
  EXPECT_TRUE(is_black(bsdf.albedo()));
}

TEST(Bsdf, DeltaFlagsFollowRoughness) {
  EXPECT_TRUE(Bsdf(mirror(Vec3(1.0f))).is_delta());
  EXPECT_TRUE(Bsdf(dielectric(0.0f)).is_delta());
  EXPECT_FALSE(Bsdf(dielectric(0.01f)).is_delta());
  EXPECT_FALSE(Bsdf(ggx(0.0f)).is_delta());  // alpha clamped to 1e-3
  EXPECT_FALSE(Bsdf(diffuse(Vec3(0.5f))).is_delta());
  EXPECT_FALSE(Bsdf(phong(10)).is_delta());
  EXPECT_TRUE(Bsdf(diffuse(Vec3(0.5f))).scatters());
}

}  // namespace
}  // namespace pdrt

namespace pdrt {
namespace {

// ---- Conductor: exact complex Fresnel, named metals, rough GGX lobe.

// The published entries (wavelength in um, n, k) that bracket 650 / 550 / 450 nm, copied from the
// tables themselves (Johnson & Christy 1972 for Au, Ag, Cu; Rakic 1995 for Al), independently of
// the constants in renderer/scene/material.cpp. The published normal-incidence reflectance at a
// channel's wavelength is R = ((n-1)^2 + k^2) / ((n+1)^2 + k^2) of each bracketing entry,
// interpolated linearly in wavelength.
struct PublishedNk {
  double um, n, k;
};
struct MetalTable {
  const char* name;
  PublishedNk rows[6];  // ascending wavelength: two entries around 450, 550 and 650 nm
};
constexpr MetalTable kPublished[] = {
    {"Au",
     {{0.4305, 1.45, 1.948},
      {0.4509, 1.38, 1.914},
      {0.5209, 0.62, 2.081},
      {0.5486, 0.43, 2.455},
      {0.6168, 0.21, 3.272},
      {0.6595, 0.14, 3.697}}},
    {"Ag",
     {{0.4305, 0.04, 2.462},
      {0.4509, 0.04, 2.657},
      {0.5209, 0.05, 3.324},
      {0.5486, 0.06, 3.586},
      {0.6168, 0.06, 4.152},
      {0.6595, 0.05, 4.483}}},
    {"Cu",
     {{0.4305, 1.25, 2.305},
      {0.4509, 1.24, 2.397},
      {0.5209, 1.18, 2.608},
      {0.5486, 1.02, 2.577},
      {0.6168, 0.30, 3.205},
      {0.6595, 0.22, 3.747}}},
    {"Al",
     {{0.4428, 0.6079, 5.3676},
      {0.47687, 0.7278, 5.7781},
      {0.5166, 0.8734, 6.2418},
      {0.56357, 1.0728, 6.7839},
      {0.61993, 1.3660, 7.4052},
      {0.65225, 1.5724, 7.7354}}},
};

double published_r0(const MetalTable& t, double um) {
  for (int i = 0; i + 1 < 6; ++i) {
    const PublishedNk &a = t.rows[i], &b = t.rows[i + 1];
    if (a.um <= um && um <= b.um) {
      double s = (um - a.um) / (b.um - a.um);
      return (1 - s) * conductor_r0(a.n, a.k) + s * conductor_r0(b.n, b.k);
    }
  }
  ADD_FAILURE() << t.name << ": no entries bracket " << um << " um";
  return 0;
}

TEST(Conductor, FresnelAtNormalIncidenceIsR0OfEachNamedMetal) {
  const double channel_um[3] = {0.65, 0.55, 0.45};
  for (const MetalTable& t : kPublished) {
    const NamedMetal* nm = find_named_metal(t.name);
    ASSERT_NE(nm, nullptr) << t.name;
    for (int c = 0; c < 3; ++c) {
      double r0 = conductor_r0(nm->eta[c], nm->k[c]);
      // The exact Fresnel equals the closed form at cos = 1 to double rounding.
      EXPECT_NEAR(fresnel_conductor(1.0, nm->eta[c], nm->k[c]), r0, 1e-12) << t.name << " channel " << c;
      // And the published reflectance within 1 % (relative).
      double published = published_r0(t, channel_um[c]);
      EXPECT_LE(rel_diff(r0, published), 0.01)
          << t.name << " channel " << c << " R0 " << r0 << " published " << published;
    }
  }
}

TEST(Conductor, ZeroExtinctionIsTheDielectricFresnel) {
  // k = 0: the complex formula reduces to fresnel_dielectric, also for eta < 1 beyond the critical
  // angle (total internal reflection). Tolerance 1e-12 (double rounding).
  for (double eta : {0.67, 1.33, 1.5, 2.4})
    for (double cos_i : {1.0, 0.9, 0.7, 0.5, 0.3, 0.1, 0.01})
      EXPECT_NEAR(fresnel_conductor(cos_i, eta, 0.0), fresnel_dielectric(cos_i, eta), 1e-12)
          << "eta " << eta << " cos " << cos_i;
}

TEST(Conductor, FresnelTendsToOneAtGrazing) {
  // F(cos) -> 1 as cos -> 0 for every metal and channel: within 2e-3 at cos = 1e-4, exactly 1 at 0,
  // and F increases toward grazing over the last 5 degrees.
  for (const MetalTable& m : kPublished) {
    const NamedMetal* nm = find_named_metal(m.name);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(fresnel_conductor(0.0, nm->eta[c], nm->k[c]), 1.0, 1e-12);
      EXPECT_NEAR(fresnel_conductor(1e-4, nm->eta[c], nm->k[c]), 1.0, 2e-3) << m.name << " " << c;
      EXPECT_LT(fresnel_conductor(std::cos(85 * M_PI / 180), nm->eta[c], nm->k[c]),
                fresnel_conductor(std::cos(89.9 * M_PI / 180), nm->eta[c], nm->k[c]));
    }
  }
}

TEST(Conductor, SmoothConductorIsADeltaMirrorWeightedByExactFresnel) {
  Bsdf bsdf(metal("Cu", 0.0f));
  EXPECT_TRUE(bsdf.is_delta());
  const NamedMetal* nm = find_named_metal("Cu");
  for (float t : {0.0f, 40.0f, 80.0f}) {
    Vec3 wo = direction(t);
    BsdfSample s;
    ASSERT_TRUE(bsdf.sample(wo, 0.3f, 0.6f, 0.5f, &s));
    EXPECT_TRUE(s.delta);
    EXPECT_FLOAT_EQ(s.wi.z, wo.z);
    EXPECT_FLOAT_EQ(s.wi.x, -wo.x);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], fresnel_conductor(wo.z, nm->eta[c], nm->k[c]), 1e-6);
    EXPECT_EQ(bsdf.eval(wo, s.wi).x, 0.0f);
  }
}

TEST(Conductor, RoughConductorIsReciprocal) {
  // f(wo, wi) = f(wi, wo) within 1e-4 relative, with and without energy compensation.
  Rng rng(77);
  for (const char* name : {"Au", "Al"})
    for (float r : {0.2f, 0.5f, 0.9f})
      for (bool comp : {false, true}) {
        Material m = metal(name, r);
        m.energy_compensation = comp;
        Bsdf bsdf(m);
        int nonzero = 0;
        for (int i = 0; i < 5000; ++i) {
          Vec3 wo = uniform_sphere(rng), wi = uniform_sphere(rng);
          wo.z = std::abs(wo.z), wi.z = std::abs(wi.z);
          Vec3 a = bsdf.eval(wo, wi), b = bsdf.eval(wi, wo);
          for (int c = 0; c < 3; ++c) {
            if (a[c] < 1e-12f && b[c] < 1e-12f) continue;
            ++nonzero;
            ASSERT_LE(rel_diff(a[c], b[c]), 1e-4) << name << " r " << r << " channel " << c;
          }
        }
        EXPECT_GT(nonzero, 1000);
      }
}

TEST(Conductor, PerfectConductorFurnaceStaysWithinTheGlossyBounds) {
  // A conductor with k = 1e4 has F = 1 to 2e-4 at every angle (R0 = 1 - 4 eta / ((eta+1)^2 + k^2)).
  // Same bounds as GlossyGgxNeverCreatesEnergy: mean weight <= 1 + 3 sigma (+ 3e-3 with
  // compensation); and, with compensation, no more than 3 % lost as in test_energy_compensation.cpp (E_ss alone loses
  // up to 60 %).
  EXPECT_GT(fresnel_conductor(0.05, 1.0, 1e4), 1.0 - 2e-4);
  for (bool comp : {false, true})
    for (float r : {0.05f, 0.2f, 0.5f, 0.9f, 1.0f})
      for (float t : {0.0f, 45.0f, 70.0f, 85.0f}) {
        Material m = conductor(r, Vec3(1.0f), Vec3(1e4f));
        m.energy_compensation = comp;
        Estimate e = mean_weight(Bsdf(m), direction(t), 11, 50000);
        EXPECT_LE(e.mean, 1.0 + 3.0 * e.sigma + (comp ? 3e-3 : 0.0)) << "roughness " << r << " theta " << t;
        if (comp) {
          EXPECT_GT(e.mean, 0.97 - 3.0 * e.sigma) << "roughness " << r << " theta " << t;
        }
      }
}

TEST(Conductor, PerfectConductorMatchesWhiteSchlickGlossy) {
  // F = 1 both ways: the rough conductor's eval equals the white GGX glossy's within 1e-3 relative.
  Rng rng(5);
  Bsdf c(conductor(0.5f, Vec3(1.0f), Vec3(1e4f))), g(ggx(0.5f, Vec3(1.0f)));
  for (int i = 0; i < 2000; ++i) {
    Vec3 wo = uniform_sphere(rng), wi = uniform_sphere(rng);
    wo.z = std::abs(wo.z), wi.z = std::abs(wi.z);
    float a = c.eval(wo, wi).x, b = g.eval(wo, wi).x;
    if (a < 1e-12f && b < 1e-12f) continue;
    ASSERT_LE(rel_diff(a, b), 1e-3);
  }
}

TEST(Conductor, DeltaOnlyAtRoughnessZero) {
  EXPECT_TRUE(Bsdf(metal("Ag", 0.0f)).is_delta());
  EXPECT_FALSE(Bsdf(metal("Ag", 0.3f)).is_delta());
  EXPECT_TRUE(Bsdf(metal("Ag", 0.3f)).scatters());
}

// The path tracer does not draw a value a lobe says it ignores (Bsdf::uses_direction,
// uses_lobe_choice), so the claim must hold: sample() with any other value gives the same
// result, bit for bit, for every lobe that makes it; and the lobes that read a value say so.
TEST(Bsdf, ALobeThatIgnoresAValueSamplesTheSameWithAnyValue) {
  Material uncompensated = ggx(0.4f, Vec3(0.7f)), emitter;
  uncompensated.energy_compensation = false;
  emitter.type = MaterialType::Emitter;
  Material thin = dielectric(0.0f);
  thin.type = MaterialType::ThinDielectric;
  const std::vector<std::pair<const char*, Material>> materials = {{"diffuse", diffuse(Vec3(0.5f))},
                                                                   {"phong", phong(20)},
                                                                   {"ggx", ggx(0.4f, Vec3(0.7f))},
                                                                   {"ggx uncompensated", uncompensated},
                                                                   {"mirror", mirror(Vec3(0.9f))},
                                                                   {"smooth conductor", metal("Au", 0)},
                                                                   {"rough conductor", metal("Au", 0.3f)},
                                                                   {"smooth dielectric", dielectric(0)},
                                                                   {"rough dielectric", dielectric(0.3f)},
                                                                   {"thin dielectric", thin},
                                                                   {"emitter", emitter}};
  auto eq = [](const Vec3& p, const Vec3& q) { return p.x == q.x && p.y == q.y && p.z == q.z; };
  auto same = [&](bool a, const BsdfSample& x, bool b, const BsdfSample& y) {
    return a == b && (!a || (eq(x.wi, y.wi) && eq(x.weight, y.weight) && x.pdf == y.pdf && x.delta == y.delta &&
                             x.transmission == y.transmission && x.eta == y.eta));
  };
  int ignoring = 0;
  Rng rng(3);
  for (const auto& [name, m] : materials) {
    const Bsdf b(m);
    ignoring += !b.uses_direction() + !b.uses_lobe_choice();
    int differs_u = 0, differs_c = 0;
    for (int i = 0; i < 500; ++i) {
      Vec3 wo = uniform_sphere(rng);
      if (i % 2) wo.z = std::abs(wo.z);
      const float u1 = float(rng.uniform()), u2 = float(rng.uniform()), uc = float(rng.uniform());
      BsdfSample a, d, c;
      const bool ra = b.sample(wo, u1, u2, uc, &a);
      const bool rd = b.sample(wo, float(rng.uniform()), float(rng.uniform()), uc, &d);
      const bool rc = b.sample(wo, u1, u2, float(rng.uniform()), &c);
      differs_u += !same(ra, a, rd, d), differs_c += !same(ra, a, rc, c);
    }
    if (!b.uses_direction()) {
      EXPECT_EQ(differs_u, 0) << name;
    }
    if (!b.uses_lobe_choice()) {
      EXPECT_EQ(differs_c, 0) << name;
    }
    if (b.uses_direction() && b.scatters() && !b.is_delta()) {
      EXPECT_GT(differs_u, 0) << name;
    }
  }
  // diffuse, phong, uncompensated ggx: the choice; mirror, smooth conductor, emitter: both;
  // smooth and thin dielectric: the direction.
  EXPECT_EQ(ignoring, 11);
}

}  // namespace
}  // namespace pdrt
