// coated_diffuse (renderer/render/bxdf/coated_diffuse.h): a Lambert base under a smooth or GGX-rough
// dielectric coat. Sampling against pdf (chi-square, delta lobe as its own category), weights
// against eval, reciprocity, white furnace (directional albedo and a rendered sphere), the
// black base (the coat's albedo alone), Beer-Lambert absorption, degenerate input.
#include "renderer/render/bsdf.h"
#include "renderer/render/fresnel.h"
#include "renderer/render/ggx_albedo.h"
#include "sampling/core/rng.h"
#include "tests/support/bsdf_chi_square.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/sphere_quadrature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace pdrt {
namespace {

using namespace pdrt::test;

Material coated(float roughness, Vec3 albedo = Vec3(1.0f), float ior = 1.5f, Vec3 coat_color = Vec3(1.0f),
                float thickness = 1.0f) {
  Material m;
  m.name = "coated";
  m.type = MaterialType::CoatedDiffuse;
  m.roughness = roughness;
  m.albedo = albedo;
  m.ior = ior;
  m.coat_color = coat_color;
  m.coat_thickness = thickness;
  return m;
}

Vec3 wo_at(float mu, float phi = 0.7f) {
  float s = std::sqrt(std::max(0.0f, 1 - mu * mu));
  return {s * std::cos(phi), s * std::sin(phi), mu};
}

Vec3 direction(float theta_deg, float phi = 0.7f) { return wo_at(std::cos(theta_deg * kPi / 180.0f), phi); }

Vec3 uniform_hemisphere(Rng& rng) {
  double z = rng.uniform(), phi = 2.0 * M_PI * rng.uniform();
  double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::max(z, 1e-6))};
}

struct Estimate {
  double mean[3], sigma[3];
};

// Directional albedo from wo: the mean path weight of sample() (delta samples included,
// failures count 0), per channel, with its standard error.
Estimate sampled_albedo(const Bsdf& bsdf, const Vec3& wo, uint64_t seed, int n) {
  Rng rng(seed);
  double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    BsdfSample s;
    if (!bsdf.sample(wo, uniform_float(rng), uniform_float(rng), uniform_float(rng), &s)) continue;
    for (int k = 0; k < 3; ++k) sum[k] += s.weight[k], sum2[k] += double(s.weight[k]) * s.weight[k];
  }
  Estimate e;
  for (int k = 0; k < 3; ++k) {
    e.mean[k] = sum[k] / n;
    e.sigma[k] = std::sqrt(std::max(0.0, sum2[k] / n - e.mean[k] * e.mean[k]) / n);
  }
  return e;
}

// ---- Sampling matches pdf: chi-square over (cos theta, phi) bins, the smooth coat's delta
// reflection a category of its own (expected with the probability its samples report).

struct FitCase {
  std::string name;
  Material material;
  Vec3 wo;
};

std::vector<FitCase> fit_cases() {
  std::vector<FitCase> cases;
  auto deg = [](float t) { return std::to_string(int(t)); };
  for (float t : {0.0f, 60.0f, 85.0f}) cases.push_back({"Smooth_theta" + deg(t), coated(0, Vec3(0.5f)), direction(t)});
  cases.push_back({"SmoothAbsorbing_theta45", coated(0, Vec3(0.8f, 0.5f, 0.2f), 2.0f, Vec3(0.9f, 0.6f, 0.3f), 0.5f),
                   direction(45)});
  for (int r : {2, 5, 10})
    for (float t : {0.0f, 60.0f, 85.0f})
      cases.push_back({"Rough_r" + std::to_string(r / 10) + "p" + std::to_string(r % 10) + "_theta" + deg(t),
                       coated(0.1f * r, Vec3(0.5f)), direction(t)});
  cases.push_back(
      {"RoughAbsorbing_r0p3_theta70", coated(0.3f, Vec3(0.9f), 1.33f, Vec3(0.5f, 0.7f, 0.9f)), direction(70)});
  return cases;
}

void PrintTo(const FitCase& c, std::ostream* os) { *os << c.name; }

class CoatedSampleMatchesPdf : public ::testing::TestWithParam<FitCase> {};

TEST_P(CoatedSampleMatchesPdf, ChiSquareAndTotalProbability) {
  const FitCase& c = GetParam();
  Bsdf bsdf(c.material);
  const int64_t n = 500000;
  uint64_t seed = 4321;  // from the case name: the same on every standard library
  for (char ch : c.name) seed = hash_combine(seed, uint64_t(ch));
  FitResult r = chi_square_fit(bsdf, c.wo, seed, n);
  // Significance 0.01 for the family, Sidak-corrected over its cases.
  const double alpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / double(fit_cases().size()));
  EXPECT_GT(r.p, alpha) << "chi2 = " << r.statistic << " dof = " << r.dof;
  std::printf("%s: chi2 %.1f dof %.0f p %.3f\n", c.name.c_str(), r.statistic, r.dof, r.p);
  EXPECT_EQ(r.zero_pdf_samples, 0);
  EXPECT_EQ(r.pdf_mismatches, 0);
  EXPECT_EQ(r.delta_mismatches, 0);
  // Only the smooth coat has a delta lobe.
  EXPECT_EQ(r.delta_probability > 0, c.material.roughness == 0);
  // pdf() integrates to the probability of a successful non-delta sample: 4 binomial sigma,
  // plus 1e-4 for the quadrature.
  double s = r.success_fraction - r.delta_probability;
  EXPECT_NEAR(r.pdf_integral, s, 4.0 * std::sqrt(s * (1 - s) / double(n)) + 1e-4);
}

INSTANTIATE_TEST_SUITE_P(CoatedDiffuse, CoatedSampleMatchesPdf, ::testing::ValuesIn(fit_cases()),
                         [](const ::testing::TestParamInfo<FitCase>& info) { return info.param.name; });

// ---- Weights, delta handling, degenerate input.

TEST(CoatedDiffuse, SampleWeightIsEvalCosOverPdf) {
  // Non-delta samples: pdf equals pdf() and the weight f cos / pdf, 1e-3 relative (float).
  Rng rng(91);
  for (const Material& m : {coated(0, Vec3(0.2f, 0.5f, 0.9f)), coated(0.3f, Vec3(0.7f)), coated(0.8f, Vec3(1.0f), 2.4f),
                            coated(0.5f, Vec3(0.6f), 1.5f, Vec3(0.4f, 0.8f, 1.0f), 2.0f)}) {
    Bsdf bsdf(m);
    int non_delta = 0;
    for (float t : {0.0f, 30.0f, 60.0f, 80.0f, 89.0f}) {
      Vec3 wo = direction(t, 0.3f);
      for (int i = 0; i < 2000; ++i) {
        BsdfSample s;
        if (!bsdf.sample(wo, uniform_float(rng), uniform_float(rng), uniform_float(rng), &s)) continue;
        ASSERT_FALSE(s.transmission);
        ASSERT_GT(s.wi.z, 0.0f);
        ASSERT_NEAR(length(s.wi), 1.0f, 1e-5f);
        if (s.delta) continue;
        ++non_delta;
        float p = bsdf.pdf(wo, s.wi);
        ASSERT_LE(rel_diff(p, s.pdf), 1e-3) << "theta " << t;
        Vec3 expect = bsdf.eval(wo, s.wi) * (s.wi.z / p);
        for (int k = 0; k < 3; ++k) ASSERT_LE(rel_diff(s.weight[k], expect[k]), 1e-3) << "theta " << t << " k " << k;
      }
    }
    EXPECT_GT(non_delta, 1000);
  }
}

TEST(CoatedDiffuse, SmoothCoatIsOneDeltaLobeBesideTheBase) {
  // is_delta() is false (next-event estimation runs for the base); the delta sample is the
  // mirror direction with weight F(mu_o) / P(coat) and pdf P(coat); eval() and pdf() hold only
  // the base, so the mirror direction evaluates to the base's value.
  Material m = coated(0, Vec3(0.5f));
  Bsdf bsdf(m);
  CoatedDiffuse model(m);
  EXPECT_FALSE(bsdf.is_delta());
  EXPECT_TRUE(bsdf.scatters());
  for (float t : {0.0f, 45.0f, 80.0f}) {
    Vec3 wo = direction(t);
    float p = model.coat_probability(wo.z);
    ASSERT_GT(p, 0.0f);
    ASSERT_LT(p, 1.0f);
    BsdfSample s;
    ASSERT_TRUE(bsdf.sample(wo, 0.3f, 0.6f, 0.5f * p, &s));
    EXPECT_TRUE(s.delta);
    EXPECT_FLOAT_EQ(s.pdf, p);
    EXPECT_FLOAT_EQ(s.wi.z, wo.z);
    EXPECT_FLOAT_EQ(s.wi.x, -wo.x);
    EXPECT_NEAR(s.weight.x * p, fresnel_dielectric(wo.z, 1.5), 1e-6);
    float base_pdf = (1 - p) * wo.z * kInvPi;
    EXPECT_NEAR(bsdf.pdf(wo, s.wi), base_pdf, 1e-6f * base_pdf);
    // Base lobe: 0.5 (1 - F(mu_o)) (1 - F(mu_i)) / (pi eta^2 (1 - 0.5 F_in)).
    double f_in = 1 - (1 - fresnel_dielectric_average(1.5)) / 2.25, fo = fresnel_dielectric(wo.z, 1.5);
    double base = 0.5 * (1 - fo) * (1 - fo) / (M_PI * 2.25 * (1 - 0.5 * f_in));
    EXPECT_NEAR(bsdf.eval(wo, s.wi).x, base, 1e-5 * base);
    ASSERT_TRUE(bsdf.sample(wo, 0.3f, 0.6f, p + 0.5f * (1 - p), &s));
    EXPECT_FALSE(s.delta);
  }
  EXPECT_FALSE(Bsdf(coated(0.3f)).is_delta());
}

TEST(CoatedDiffuse, DirectionsBelowTheSurfaceGiveNothing) {
  for (float r : {0.0f, 0.5f}) {
    Bsdf bsdf(coated(r, Vec3(0.5f)));
    Vec3 up = direction(30), down = -direction(40);
    BsdfSample s;
    EXPECT_FALSE(bsdf.sample(down, 0.3f, 0.4f, 0.5f, &s));
    EXPECT_FALSE(bsdf.sample(down, 0.3f, 0.4f, 0.01f, &s));
    EXPECT_FALSE(bsdf.sample(Vec3(1, 0, 0), 0.3f, 0.4f, 0.5f, &s));
    EXPECT_TRUE(is_black(bsdf.eval(down, up)));
    EXPECT_TRUE(is_black(bsdf.eval(up, down)));
    EXPECT_EQ(bsdf.pdf(up, down), 0.0f);
    EXPECT_EQ(bsdf.pdf(down, up), 0.0f);
  }
}

TEST(CoatedDiffuse, SamplesAreFiniteAtTheCornersOfTheUnitSquare) {
  const float one_minus = 0x1.fffffep-1f;
  for (const Material& m :
       {coated(0), coated(0.001f), coated(1.0f), coated(0, Vec3(0.0f)), coated(0.5f, Vec3(0.0f), 1.0f),
        coated(0, Vec3(1.0f), 1.0f, Vec3(0.0f)), coated(0.4f, Vec3(1.0f), 3.0f, Vec3(0.0f, 0.5f, 1.0f), 1e30f)}) {
    Bsdf bsdf(m);
    for (float t : {0.0f, 45.0f, 89.9f, 89.999f})
      for (float u1 : {0.0f, 0.5f, one_minus})
        for (float u2 : {0.0f, 0.5f, one_minus})
          for (float uc : {0.0f, 0.5f, one_minus}) {
            Vec3 wo = direction(t);
            BsdfSample s;
            if (!bsdf.sample(wo, u1, u2, uc, &s)) continue;
            ASSERT_TRUE(is_finite(s.wi) && is_finite(s.weight) && std::isfinite(s.pdf));
            ASSERT_GT(s.pdf, 0.0f);
            ASSERT_GE(std::min({s.weight.x, s.weight.y, s.weight.z}), 0.0f);
            ASSERT_NEAR(length(s.wi), 1.0f, 1e-5f);
            ASSERT_TRUE(is_finite(bsdf.eval(wo, s.wi)) && std::isfinite(bsdf.pdf(wo, s.wi)));
          }
  }
}

// ---- Reciprocity.

TEST(CoatedDiffuse, IsReciprocal) {
  // f(wo, wi) = f(wi, wo) within 1e-4 relative (float rounding of a symmetric formula), per
  // channel, smooth and rough, clear and absorbing.
  Rng rng(17);
  for (const Material& m : {coated(0, Vec3(0.3f, 0.6f, 0.9f)), coated(0.2f, Vec3(0.5f)), coated(0.6f, Vec3(0.9f), 2.0f),
                            coated(1.0f, Vec3(0.7f), 1.33f, Vec3(0.5f, 0.8f, 0.95f), 1.5f)}) {
    Bsdf bsdf(m);
    for (int i = 0; i < 10000; ++i) {
      Vec3 wo = uniform_hemisphere(rng), wi = uniform_hemisphere(rng);
      // Half the pairs near the mirror direction, where the rough coat's lobe is large.
      if (i % 2) wi = normalize(Vec3{-wo.x, -wo.y, wo.z} + 0.2f * uniform_hemisphere(rng)), wi.z = std::abs(wi.z);
      Vec3 a = bsdf.eval(wo, wi), b = bsdf.eval(wi, wo);
      for (int k = 0; k < 3; ++k) {
        ASSERT_GT(a[k], 0.0f);
        ASSERT_LE(rel_diff(a[k], b[k]), 1e-4) << "roughness " << m.roughness << " channel " << k;
      }
    }
  }
}

// ---- Energy.

// White base, clear coat: the directional albedo (sampled, delta part included) is 1 - (E_true -
// E_table) of the coat: within [0.95, 1 + 3 sigma + 3e-3] (the coat table's accuracy, as in
// GgxAlbedo.CoatTableMatchesBruteForce; the smooth coat is exact: 1 + 3 sigma + 1e-5).
TEST(CoatedDiffuse, WhiteFurnaceReflectsAllTheLight) {
  std::printf("white furnace (albedo 1, clear coat, ior 1.5): directional albedo\n  roughness");
  const float mus[] = {0.1f, 0.3f, 0.5f, 0.7f, 1.0f};
  for (float mu : mus) std::printf("   mu %.1f ", mu);
  std::printf("\n");
  for (float r : {0.0f, 0.3f, 0.7f, 1.0f}) {
    Bsdf bsdf(coated(r));
    std::printf("  %.1f      ", r);
    for (float mu : mus) {
      Estimate e = sampled_albedo(bsdf, wo_at(mu), 1000 + int(100 * mu), 200000);
      std::printf("  %.4f  ", e.mean[0]);
      EXPECT_GE(e.mean[0], 0.95) << "roughness " << r << " mu " << mu;
      EXPECT_LE(e.mean[0], 1.0 + 3.0 * e.sigma[0] + (r == 0 ? 1e-5 : 3e-3)) << "roughness " << r << " mu " << mu;
    }
    std::printf("\n");
  }
}

TEST(CoatedDiffuse, SmoothWhiteFurnaceIsExactlyOneByQuadrature) {
  // F(mu_o) + the integral of eval() cos over the hemisphere: 1 within 1e-4 (the quadrature's
  // accuracy), for several indices; sampling plays no part.
  for (float ior : {1.2f, 1.5f, 2.4f})
    for (float mu : {0.05f, 0.4f, 1.0f}) {
      Bsdf bsdf(coated(0, Vec3(1.0f), ior));
      double diffuse = test::integrate_sphere(
          [&](const Vec3& wi) { return double(bsdf.eval(wo_at(mu), wi).x) * std::abs(wi.z); }, 512, 64);
      EXPECT_NEAR(fresnel_dielectric(mu, ior) + diffuse, 1.0, 1e-4) << "ior " << ior << " mu " << mu;
    }
}

TEST(CoatedDiffuse, BlackBaseReflectsTheCoatAlone) {
  // Albedo 0: the smooth coat's directional albedo is F(mu_o) (every sample is the delta
  // reflection); the rough coat's is its reflection albedo E(mu_o), the table within 3e-3.
  for (float mu : {0.1f, 0.5f, 1.0f}) {
    Estimate s = sampled_albedo(Bsdf(coated(0, Vec3(0.0f))), wo_at(mu), 7, 1000);
    EXPECT_NEAR(s.mean[0], fresnel_dielectric(mu, 1.5), 1e-6) << "mu " << mu;
    EXPECT_LT(s.sigma[0], 1e-6);  // every weight is F(mu_o), up to float rounding
    for (float r : {0.3f, 0.7f, 1.0f}) {
      Estimate e = sampled_albedo(Bsdf(coated(r, Vec3(0.0f))), wo_at(mu), 8, 200000);
      EXPECT_NEAR(e.mean[0], ggx_coat_albedo(mu, r * r, 1.5f), 3.0 * e.sigma[0] + 3e-3)
          << "roughness " << r << " mu " << mu;
    }
  }
}

TEST(CoatedDiffuse, AbsorbingCoatReflectsStrictlyLess) {
  // Same base and coat, coat_color 0.7 in one channel: f is lower for every pair of directions
  // in that channel, unchanged in the clear ones, and the sampled albedo is lower by > 5 sigma
  // there (the clear channel's within 4 sigma: the lobe choice differs, so the samples do).
  Rng rng(23);
  for (float r : {0.0f, 0.5f}) {
    Bsdf clear(coated(r, Vec3(0.8f))), tinted(coated(r, Vec3(0.8f), 1.5f, Vec3(1.0f, 0.7f, 1.0f)));
    for (int i = 0; i < 2000; ++i) {
      Vec3 wo = uniform_hemisphere(rng), wi = uniform_hemisphere(rng);
      Vec3 a = clear.eval(wo, wi), b = tinted.eval(wo, wi);
      ASSERT_LT(b.y, a.y);
      ASSERT_FLOAT_EQ(b.x, a.x);
    }
    for (float mu : {0.2f, 1.0f}) {
      Estimate a = sampled_albedo(clear, wo_at(mu), 5, 100000), b = sampled_albedo(tinted, wo_at(mu), 5, 100000);
      EXPECT_LT(b.mean[1], a.mean[1] - 5 * std::hypot(a.sigma[1], b.sigma[1])) << "roughness " << r << " mu " << mu;
      EXPECT_NEAR(b.mean[0], a.mean[0], 4 * std::hypot(a.sigma[0], b.sigma[0])) << "roughness " << r << " mu " << mu;
    }
  }
}

TEST(CoatedDiffuse, BeerLambertAtNormalIncidence) {
  // An index-matched coat (ior 1: no Fresnel, no refraction) of colour c and thickness d over
  // a base rho: f(n, n) = rho c^(2d) / pi (one pass down, one up), to 1e-6 relative, and the
  // directional albedo at normal incidence rho c^d 2 int_0^1 c^(d / mu) mu dmu (the exit pass
  // along mu), against a 1e5-point midpoint rule, within 3 sigma of the sampled estimate.
  const float rho = 0.8f, c = 0.6f, d = 0.5f;
  Bsdf bsdf(coated(0, Vec3(rho), 1.0f, Vec3(c), d));
  Vec3 n{0, 0, 1};
  EXPECT_NEAR(bsdf.eval(n, n).x, rho * std::pow(c, 2 * d) / M_PI, 1e-6 * rho / M_PI);
  double exit = 0;
  const int m = 100000;
  for (int i = 0; i < m; ++i) {
    double mu = (i + 0.5) / m;
    exit += 2 * std::pow(double(c), d / mu) * mu / m;
  }
  double expected = rho * std::pow(double(c), double(d)) * exit;
  Estimate e = sampled_albedo(bsdf, n, 3, 200000);
  EXPECT_NEAR(e.mean[0], expected, 3 * e.sigma[0]) << "expected " << expected;
  EXPECT_LT(expected, 0.8 * rho * std::pow(double(c), double(d)));  // the exit pass absorbs too
}

TEST(CoatedDiffuse, ClosedFormFresnelAverageMatchesQuadrature) {
  // fresnel_dielectric_average_closed against composite Simpson of 2 F(mu) mu dmu in mu (F is
  // smooth in mu for eta > 1; 2e5 intervals resolve even eta = 1 + 1e-5): 2e-8 absolute, also
  // where the closed form hands over to its first order near eta = 1.
  for (double eta : {1.0, 1.00001, 1.00003, 1.0001, 1.001, 1.01, 1.2, 1.33, 1.5, 2.0, 2.4, 3.0}) {
    const int n = 200000;
    double s = 0;
    for (int i = 0; i <= n; ++i) {
      double mu = double(i) / n, w = i == 0 || i == n ? 1 : i % 2 ? 4 : 2;
      s += w * 2 * fresnel_dielectric(mu, eta) * mu;
    }
    EXPECT_NEAR(fresnel_dielectric_average_closed(eta), s / (3.0 * n), 2e-8) << "eta " << eta;
  }
}

// ---- A rendered white furnace.

// A unit sphere of white base and clear coat in a constant white environment: the pixels
// inside 0.8 of its silhouette average 1 within 1 % (64 spp over ~300 pixels), smooth and rough.
TEST(CoatedDiffuse, RenderedWhiteFurnaceSphereShowsTheEnvironment) {
  for (float r : {0.0f, 0.5f}) {
    const Vec3 centre(10, -5, 30);
    SceneDesc s = furnace_sphere(32, 32, 64, centre, coated(r));
    s.integrator.max_depth = 16;
    Image im = render_quietly(s).image;
    double sum = 0;
    int n = 0;
    for (auto [x, y] : pixels_inside_silhouette(s, centre, 0.8)) sum += mean_rgb(im, x, y), ++n;
    ASSERT_GT(n, 100);
    std::printf("coated_diffuse roughness %.1f: rendered furnace %.4f\n", r, sum / n);
    EXPECT_NEAR(sum / n, 1.0, 0.01) << "roughness " << r;
  }
}

}  // namespace
}  // namespace pdrt
