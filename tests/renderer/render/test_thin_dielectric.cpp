// The thin dielectric (pbrt-v4 §9.5.1's ThinDielectricBxDF): R' + T' = 1 at every angle, R'
// against the closed form at normal and grazing incidence, the sampled reflect/transmit
// frequencies against R' and T', straight-through transmission, and a rendered white furnace.
#include "renderer/render/bsdf.h"
#include "sampling/core/rng.h"
#include "tests/support/bsdf_chi_square.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace pdrt {
namespace {

using namespace pdrt::test;

Material thin(float ior, Vec3 albedo = Vec3(1.0f)) {
  Material m;
  m.type = MaterialType::ThinDielectric;
  m.ior = ior;
  m.albedo = albedo;
  return m;
}

Vec3 at_angle(double cos_theta, float sign = 1) {
  const double s = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  return {float(s * 0.6), float(s * 0.8), float(sign * cos_theta)};
}

// Fresnel of unpolarised light from the textbook s/p amplitudes (Born & Wolf §1.5), written out
// independently of fresnel.cpp; then the slab's series R + T^2 R / (1 - R^2) = 2R / (1 + R).
double slab_reflectance(double cos_i, double n) {
  const double sin_t = std::sqrt(std::max(0.0, 1 - cos_i * cos_i)) / n, cos_t = std::sqrt(1 - sin_t * sin_t);
  const double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t), rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
  const double r = 0.5 * (rs * rs + rp * rp);
  return 2 * r / (1 + r);
}

TEST(ThinDielectric, ReflectedAndTransmittedSumToOneAtEveryAngle) {
  const Bsdf b(thin(1.5f));
  for (int i = 0; i <= 100; ++i) {
    const double c = std::max(1e-4, i / 100.0);
    for (float side : {1.0f, -1.0f}) {
      BsdfSample r, t;
      ASSERT_TRUE(b.sample(at_angle(c, side), 0.3f, 0.6f, 0.0f, &r)) << c;
      ASSERT_TRUE(b.sample(at_angle(c, side), 0.3f, 0.6f, 0x1.fffffep-1f, &t)) << c;
      ASSERT_FALSE(r.transmission);
      ASSERT_TRUE(t.transmission) << "cos " << c;
      // Each lobe's weight is 1 (white): f cos / p = R' / R' and T' / T'.
      EXPECT_EQ(r.weight.y, 1.0f);
      EXPECT_EQ(t.weight.y, 1.0f);
      EXPECT_NEAR(double(r.pdf) + t.pdf, 1.0, 1e-6) << "cos " << c << " side " << side;
    }
  }
}

TEST(ThinDielectric, ReflectanceAtNormalAndGrazingIncidenceMatchesTheClosedForm) {
  // Normal incidence, n = 1.5: R = 0.04, R' = 2R / (1 + R) = 0.08 / 1.04.
  EXPECT_NEAR(thin_dielectric_reflectance(1.0, 1.5), 0.08 / 1.04, 1e-12);
  EXPECT_NEAR(thin_dielectric_reflectance(1.0, 1.33), slab_reflectance(1.0, 1.33), 1e-12);
  for (double c : {0.5, 0.1, 0.01, 1e-4})
    EXPECT_NEAR(thin_dielectric_reflectance(c, 1.5), slab_reflectance(c, 1.5), 1e-9) << "cos " << c;
  EXPECT_NEAR(thin_dielectric_reflectance(1e-6, 1.5), 1.0, 1e-5);  // grazing: everything reflects
  // The slab reflects more than one face and less than twice it.
  const double r1 = 0.04;
  EXPECT_GT(thin_dielectric_reflectance(1.0, 1.5), r1);
  EXPECT_LT(thin_dielectric_reflectance(1.0, 1.5), 2 * r1);
}

TEST(ThinDielectric, SampledFrequenciesMatchReflectanceAndTransmittance) {
  const Material m = thin(1.5f);
  const Bsdf b(m);
  Rng rng(17);
  for (double c : {1.0, 0.5, 0.15}) {
    const Vec3 wo = at_angle(c);
    const int n = 200000;
    int reflected = 0;
    for (int i = 0; i < n; ++i) {
      BsdfSample s;
      ASSERT_TRUE(b.sample(wo, 0.5f, 0.5f, uniform_float(rng), &s));
      ASSERT_TRUE(s.delta);
      reflected += !s.transmission;
    }
    const double p = thin_dielectric_reflectance(c, 1.5), sigma = std::sqrt(p * (1 - p) / n);
    EXPECT_NEAR(double(reflected) / n, p, 5 * sigma) << "cos " << c;  // 5 sigma of the binomial
  }
}

TEST(ThinDielectric, TransmissionGoesStraightThroughTintedByAlbedo) {
  const Bsdf b(thin(1.5f, {0.2f, 0.5f, 0.9f}));
  EXPECT_TRUE(b.is_delta());
  const Vec3 wo = at_angle(0.7);
  BsdfSample s;
  ASSERT_TRUE(b.sample(wo, 0.1f, 0.2f, 0.99f, &s));
  ASSERT_TRUE(s.transmission);
  EXPECT_EQ(s.wi.x, -wo.x);
  EXPECT_EQ(s.wi.y, -wo.y);
  EXPECT_EQ(s.wi.z, -wo.z);
  EXPECT_EQ(s.eta, 1.0f);  // no refraction, no 1/eta^2
  EXPECT_FLOAT_EQ(s.weight.x, 0.2f);
  EXPECT_FLOAT_EQ(s.weight.z, 0.9f);
  ASSERT_TRUE(b.sample(wo, 0.1f, 0.2f, 0.0f, &s));
  EXPECT_FLOAT_EQ(s.weight.x, 1.0f);  // reflection stays white
  EXPECT_EQ(s.wi.z, wo.z);
  EXPECT_EQ(b.eval(wo, -wo).y, 0.0f);  // delta: eval and pdf are 0
  EXPECT_EQ(b.pdf(wo, -wo), 0.0f);
}

// Every path through a white thin-dielectric sphere in a white environment carries weight 1:
// the furnace shows 1 (up to the paths still inside at max_depth).
TEST(ThinDielectric, RenderedWhiteFurnaceShowsTheEnvironment) {
  const Vec3 centre(0, 0, 0);
  SceneDesc s = furnace_sphere(32, 32, 16, centre, thin(1.5f));
  s.integrator.max_depth = 16;
  Image im = render_quietly(s).image;
  double sum = 0, worst = 0;
  int n = 0;
  for (auto [x, y] : pixels_inside_silhouette(s, centre, 0.9)) {
    const double v = mean_rgb(im, x, y);
    sum += v, ++n, worst = std::max(worst, std::abs(v - 1));
  }
  ASSERT_GT(n, 100);
  std::printf("thin dielectric furnace: mean %.6f, worst pixel off by %.2e\n", sum / n, worst);
  EXPECT_NEAR(sum / n, 1.0, 1e-3);
  EXPECT_LT(worst, 1e-3);
}

// An open sheet in front of an emitter, seen head-on in the dark: a pixel shows T'(0) of the
// emitter's radiance (reflection leaves toward the black sky). Each sample is 0 or L, so the
// mean over 256 pixels x 64 samples has a binomial sigma of 0.0016 L.
TEST(ThinDielectric, SheetInFrontOfAnEmitterTransmitsTheClosedForm) {
  SceneDesc s = base_scene(16, 16, 64);
  s.camera.position = {0, 0, 5}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 5;
  s.shapes.push_back(quad({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, add_material(s, thin(1.5f))));
  s.shapes.push_back(quad({-3, -3, -1}, {6, 0, 0}, {0, 6, 0}, add_material(s, emitter(2))));
  Image im = render_quietly(s).image;
  double sum = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) sum += mean_rgb(im, x, y);
  const double mean = sum / 256, expected = 2 * (1 - 0.08 / 1.04);  // rays within 2.5 degrees of normal
  std::printf("thin sheet: %.4f, 2 T' = %.4f\n", mean, expected);
  EXPECT_NEAR(mean, expected, 2 * 4 * 0.0016);  // 4 sigma
}

}  // namespace
}  // namespace pdrt
