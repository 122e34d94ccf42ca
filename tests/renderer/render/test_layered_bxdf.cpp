// The layered BSDF (renderer/render/bxdf/layered.h), pbrt-v4's LayeredBxDF behind coated_diffuse
// "model": "layered" and coated_conductor. Its stochastic f() integrated over the hemisphere,
// and the mean weight of its sample(), against an independent reference: an analog simulation
// of a particle in the slab (Fresnel or GGX-microfacet interface on top, Lambertian or
// conductor base, optional scattering medium), truncated after max_depth events as pbrt-v4's
// walk is. Also: sample() against f() bin by bin, the smooth coat's pdf in closed form,
// reciprocity, energy, a rendered furnace sphere, and images at 1 and 2 threads.
#include "renderer/render/bsdf.h"
#include "renderer/render/fresnel.h"
#include "renderer/render/microfacet_ggx.h"
#include "renderer/render/thin_lens_camera.h"
#include "sampling/core/rng.h"
#include "tests/support/bsdf_chi_square.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace pdrt {
namespace {

using namespace pdrt::test;

// pbrt-v4's roughness (remapped: alpha = sqrt(r)) as pdrt's (alpha = roughness^2).
float from_pbrt(float r) { return std::sqrt(std::sqrt(r)); }

Material coated_diffuse(float pbrt_roughness, Vec3 albedo, CoatLayers layers = {}) {
  Material m;
  m.name = "layered_diffuse";
  m.type = MaterialType::CoatedDiffuse;
  m.layered = true;
  m.roughness = from_pbrt(pbrt_roughness);
  m.albedo = albedo;
  m.ior = 1.5f;
  m.layers = layers;
  return m;
}

// Gold under the coat (pdrt's named metal), pbrt-v4's conductor roughness as the coat's.
Material coated_gold(float pbrt_roughness) {
  Material m;
  m.name = "layered_gold";
  m.type = MaterialType::CoatedConductor;
  m.layered = true;
  m.roughness = m.base_roughness = from_pbrt(pbrt_roughness);
  m.ior = 1.5f;
  m.eta = find_named_metal("Au")->eta;
  m.k = find_named_metal("Au")->k;
  return m;
}

Vec3 at_mu(double mu, double phi = 0.7) {
  double s = std::sqrt(std::max(0.0, 1 - mu * mu));
  return {float(s * std::cos(phi)), float(s * std::sin(phi)), float(mu)};
}

Vec3 cosine_direction(Rng& rng) {
  double u1 = rng.uniform(), u2 = rng.uniform(), r = std::sqrt(u1), phi = 2 * M_PI * u2;
  return {float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::sqrt(std::max(1e-12, 1 - u1)))};
}

// ---- The analog reference: one particle leaving along -wo into the slab, in double where it
// can be; a survival probability where the model loses energy (masking, absorption), a weight
// per channel where the loss is coloured (the base's reflectance or Fresnel).

struct Slab {
  double eta = 1.5, alpha = 0;  // the coat
  bool conductor = false;       // the base
  Vec3 reflectance{0.0f};       // Lambertian base
  Vec3 ceta{1.0f}, ck{0.0f};    // conductor base, relative to the coat
  double base_alpha = 0;
  CoatLayers layers;
};

Slab slab_of(const Material& m) {
  Slab s;
  s.eta = m.ior, s.alpha = double(m.roughness) * m.roughness;
  s.conductor = m.type == MaterialType::CoatedConductor;
  s.reflectance = m.albedo;
  s.ceta = m.eta / m.ior, s.ck = m.k / m.ior;
  s.base_alpha = double(m.base_roughness) * m.base_roughness;
  s.layers = m.layers;
  return s;
}

// A unit vector d arriving at a surface of normal +z from above (v = -d points up, away from it)
// meets an interface of relative index eta (below over above) with GGX alpha: the particle
// continues along the returned direction (pointing away from the surface on either side), or
// dies (false). Analog: reflect with probability F, the masking of the outgoing direction as a
// survival probability G2 / G1.
bool cross_interface(Vec3 v, double eta, double alpha, Rng& rng, Vec3* out) {
  Vec3 m{0, 0, 1};
  if (alpha >= kEffectivelySmoothAlpha)
    m = MicrofacetGgx(float(alpha)).sample_visible(v, float(rng.uniform()), float(rng.uniform()));
  double c = dot(v, m);
  if (c <= 0) return false;
  double s2 = (1 - c * c) / (eta * eta);
  double f = 1;
  if (s2 < 1) {
    double ct = std::sqrt(1 - s2), rs = (c - eta * ct) / (c + eta * ct), rp = (eta * c - ct) / (eta * c + ct);
    f = 0.5 * (rs * rs + rp * rp);
  }
  Vec3 w;
  if (rng.uniform() < f) {
    w = normalize(m * float(2 * c) - v);
    if (w.z <= 0) return false;
  } else {
    double ct = std::sqrt(1 - s2);
    w = normalize(-v / float(eta) + m * float(c / eta - ct));
    if (w.z >= 0) return false;
  }
  if (alpha >= kEffectivelySmoothAlpha) {
    const MicrofacetGgx g{float(alpha)};
    if (rng.uniform() >= g.g2(v, w) / g.g1(v)) return false;
  }
  *out = w;
  return true;
}

// The base reflects v (pointing up): a new direction up, the particle's weight scaled.
bool reflect_base(const Slab& s, Vec3 v, Rng& rng, Vec3* weight, Vec3* out) {
  if (!s.conductor) {
    *weight = *weight * s.reflectance;
    *out = cosine_direction(rng);
    return true;
  }
  Vec3 m{0, 0, 1};
  if (s.base_alpha >= kEffectivelySmoothAlpha)
    m = MicrofacetGgx(float(s.base_alpha)).sample_visible(v, float(rng.uniform()), float(rng.uniform()));
  float c = dot(v, m);
  if (c <= 0) return false;
  Vec3 w = normalize(m * (2 * c) - v);
  if (w.z <= 0) return false;
  if (s.base_alpha >= kEffectivelySmoothAlpha) {
    MicrofacetGgx g(float(s.base_alpha));
    if (rng.uniform() >= g.g2(v, w) / g.g1(v)) return false;
  }
  for (int k = 0; k < 3; ++k) (*weight)[k] *= float(fresnel_conductor(c, s.ceta[k], s.ck[k]));
  *out = w;
  return true;
}

// Henyey-Greenstein about the direction of travel t (g > 0 forward), by the textbook inversion.
Vec3 hg_scatter(const Vec3& t, double g, Rng& rng) {
  double u = rng.uniform(), c;
  if (std::abs(g) < 1e-3) {
    c = 1 - 2 * u;
  } else {
    double q = (1 - g * g) / (1 - g + 2 * g * u);
    c = (1 + g * g - q * q) / (2 * g);
  }
  double sn = std::sqrt(std::max(0.0, 1 - c * c)), phi = 2 * M_PI * rng.uniform();
  Frame f(t);
  return normalize(f.to_world(Vec3{float(sn * std::cos(phi)), float(sn * std::sin(phi)), float(c)}));
}

// The weight with which a particle leaving along -wo leaves the slab upward (0 if it dies),
// counting events as pbrt-v4's Sample_f() walk does: each segment and what ends it is one, at
// most max_depth. With `free_exit`, as pbrt-v4's f() counts them: the segment that leaves
// through the top is part of the event before it (its next-event estimate), so one more
// event, the exit, may follow the max_depth-th. Without a scattering medium the base's events
// fall on even depths and the two agree for an even max_depth.
Vec3 analog_particle(const Slab& s, const Vec3& wo, Rng& rng, bool free_exit = false) {
  Vec3 w;  // direction of travel
  if (!cross_interface(wo, s.eta, s.alpha, rng, &w)) return Vec3(0.0f);
  if (w.z > 0) return Vec3(1.0f);  // reflected at the entrance
  Vec3 weight(1.0f);
  const double h = std::max(double(s.layers.thickness), 1e-38);
  const bool scatters = !is_black(s.layers.albedo);
  double z = h;
  for (int depth = 0; depth < s.layers.max_depth + (free_exit ? 1 : 0); ++depth) {
    const bool last = depth == s.layers.max_depth;             // only the exit may happen here
    double dz = -std::log(1 - rng.uniform()) * std::abs(w.z);  // free path, extinction 1
    double zn = w.z > 0 ? z + dz : z - dz;
    if (zn > 0 && zn < h) {
      if (!scatters || last) return Vec3(0.0f);  // absorbed
      weight = weight * s.layers.albedo;
      w = hg_scatter(w, s.layers.g, rng);
      z = zn;
      continue;
    }
    if (w.z < 0) {
      if (last) return Vec3(0.0f);
      z = 0;
      if (!reflect_base(s, -w, rng, &weight, &w)) return Vec3(0.0f);
    } else {
      z = h;
      Vec3 v{-w.x, -w.y, w.z};  // seen from inside: mirrored to the upper side, index 1 / eta
      Vec3 out;
      if (!cross_interface(v, 1 / s.eta, s.alpha, rng, &out)) return Vec3(0.0f);
      if (out.z < 0) return weight;  // transmitted: out of the slab
      if (last) return Vec3(0.0f);
      w = Vec3{out.x, out.y, -out.z};
    }
  }
  return Vec3(0.0f);
}

struct Mean {
  double mean[3] = {0, 0, 0}, se[3] = {0, 0, 0};
};

template <class F>
Mean average(int n, F sample) {
  double s[3] = {0, 0, 0}, s2[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    Vec3 v = sample(i);
    for (int k = 0; k < 3; ++k) s[k] += v[k], s2[k] += double(v[k]) * v[k];
  }
  Mean m;
  for (int k = 0; k < 3; ++k) {
    m.mean[k] = s[k] / n;
    m.se[k] = std::sqrt(std::max(0.0, s2[k] / n - m.mean[k] * m.mean[k]) / n);
  }
  return m;
}

Mean analog_albedo(const Material& mat, const Vec3& wo, uint64_t seed, int n, bool free_exit = false) {
  const Slab s = slab_of(mat);
  Rng rng(seed);
  return average(n, [&](int) { return analog_particle(s, wo, rng, free_exit); });
}

// The integral of f() cos over the hemisphere by cosine-weighted directions, one key each; a
// smooth coat's entrance reflection (a delta f() leaves out) added as F(mu_o).
Mean furnace_of_eval(const Bsdf& bsdf, const Material& m, const Vec3& wo, uint64_t seed, int n) {
  Rng rng(seed);
  Mean r = average(n, [&](int i) { return bsdf.eval(wo, cosine_direction(rng), uint64_t(i) * 7919 + seed) * kPi; });
  if (m.roughness * m.roughness < kEffectivelySmoothAlpha)
    for (double& v : r.mean) v += fresnel_dielectric(wo.z, m.ior);
  return r;
}

Mean furnace_of_sample(const Bsdf& bsdf, const Vec3& wo, uint64_t seed, int n) {
  Rng rng(seed);
  return average(n, [&](int i) {
    BsdfSample s;
    float u1 = uniform_float(rng), u2 = uniform_float(rng), uc = uniform_float(rng);
    return bsdf.sample(wo, u1, u2, uc, &s, uint64_t(i) + seed) ? s.weight : Vec3(0.0f);
  });
}

struct FurnaceCase {
  std::string name;
  Material m;
};

std::vector<FurnaceCase> furnace_cases() {
  std::vector<FurnaceCase> c;
  for (float r : {0.0f, 0.15f, 0.5f}) {
    char rs[16];
    std::snprintf(rs, sizeof rs, " r %.2f", r);
    c.push_back({std::string("white diffuse") + rs, coated_diffuse(r, Vec3(1.0f))});
    c.push_back({std::string("coloured diffuse") + rs, coated_diffuse(r, Vec3(0.2f, 0.5f, 0.8f))});
    c.push_back({std::string("gold") + rs, coated_gold(r)});
  }
  CoatLayers medium;
  medium.thickness = 0.4f, medium.albedo = Vec3(0.9f, 0.6f, 0.3f), medium.g = 0.4f;
  c.push_back({"diffuse, scattering medium r 0.15", coated_diffuse(0.15f, Vec3(0.7f), medium)});
  CoatLayers thick;
  thick.thickness = 0.3f;
  c.push_back({"absorbing slab r 0.5", coated_diffuse(0.5f, Vec3(0.9f), thick)});
  return c;
}

// The same lobe with f()'s exit weighted consistently (LayeredBxdf::ExitMis::Consistent).
LayeredBxdf consistent_lobe(const Material& m) {
  const CoatInterface top(m.ior, m.roughness * m.roughness);
  const LayerBase base = m.type == MaterialType::CoatedConductor
                             ? LayerBase::conductor(m.eta / m.ior, m.k / m.ior, m.base_roughness * m.base_roughness)
                             : LayerBase::diffuse(m.albedo);
  return LayeredBxdf(top, base, m.layers, LayeredBxdf::ExitMis::Consistent);
}

Mean furnace_of_consistent_eval(const Material& m, const Vec3& wo, uint64_t seed, int n) {
  const LayeredBxdf lobe = consistent_lobe(m);
  Rng rng(seed);
  Mean r = average(n, [&](int i) { return lobe.eval(wo, cosine_direction(rng), uint64_t(i) * 7919 + seed) * kPi; });
  if (m.roughness * m.roughness < kEffectivelySmoothAlpha)
    for (double& v : r.mean) v += fresnel_dielectric(wo.z, m.ior);
  return r;
}

// (a) f() integrated over the hemisphere (its NEE and MIS estimator) and (b) sample()'s mean
// weight (its walk), each within 1 % of the analog particle, per channel, at three incident
// angles (f() against the analog counted as f() counts, `free_exit`, which differs only with a
// scattering medium); the statistical error of each side is below 0.3 % at these counts. f() as pbrt-v4
// weighs it meets the analog only under a smooth coat; with ExitMis::Consistent it meets it
// under every coat, and pbrt-v4's is brighter by the ratio printed (pbrt-v4 issue #187), at
// least 2 % at pbrt roughness 0.15 and 0.5 for a white base.
TEST(LayeredBxdf, WhiteFurnaceMatchesAnAnalogSimulationOfTheSlab) {
  std::printf("%-30s %5s %8s %8s %8s %8s %8s %7s\n", "case", "mu_o", "analog", "an. f()", "sample", "f cons.", "f pbrt",
              "ratio");
  for (const FurnaceCase& fc : furnace_cases()) {
    Bsdf bsdf(fc.m);
    const bool delta = bsdf.is_delta(), smooth_top = fc.m.roughness * fc.m.roughness < kEffectivelySmoothAlpha;
    for (double mu : {0.2, 0.6, 0.95}) {
      const Vec3 wo = at_mu(mu);
      Mean ref = analog_albedo(fc.m, wo, 11, 400000);
      Mean ref_f = is_black(fc.m.layers.albedo) ? ref : analog_albedo(fc.m, wo, 13, 400000, true);
      Mean smp = furnace_of_sample(bsdf, wo, 23, 200000);
      Mean pbrt = delta ? ref : furnace_of_eval(bsdf, fc.m, wo, 37, 200000);
      Mean cons = delta ? ref : furnace_of_consistent_eval(fc.m, wo, 37, 200000);
      std::printf("%-30s %5.2f %8.4f %8.4f %8.4f %8.4f %8.4f %7.4f\n", fc.name.c_str(), mu, ref.mean[1], ref_f.mean[1],
                  smp.mean[1], cons.mean[1], pbrt.mean[1], pbrt.mean[1] / ref_f.mean[1]);
      for (int k = 0; k < 3; ++k) {
        const double tol = 0.01 * ref.mean[k] + 1e-4;
        EXPECT_NEAR(smp.mean[k], ref.mean[k], tol) << fc.name << " mu " << mu << " channel " << k;
        const double tol_f = 0.01 * ref_f.mean[k] + 1e-4;
        EXPECT_NEAR(cons.mean[k], ref_f.mean[k], tol_f) << fc.name << " mu " << mu << " channel " << k;
        if (smooth_top) {
          EXPECT_NEAR(pbrt.mean[k], ref_f.mean[k], tol_f) << fc.name << " mu " << mu << " channel " << k;
        }
      }
      if (fc.name.rfind("white diffuse", 0) == 0 && !smooth_top) {
        EXPECT_GT(pbrt.mean[1], 1.02 * ref.mean[1]) << fc.name << " mu " << mu;
      }
    }
  }
}

// (b) sample() against f(), bin by bin: the mean of weight x [wi in bin] and the integral of
// f cos over the bin (cosine-weighted directions) agree within their standard errors; a
// chi-square over 8 x 8 (cos theta, phi) bins stays below dof + 5 sqrt(2 dof). With f()'s exit
// weighted consistently; pbrt-v4's weighting gives 714 (coated diffuse, pbrt roughness 0.15)
// and 263 (coated gold, 0.5), its f() being brighter than its Sample_f().
TEST(LayeredBxdf, SampledWeightsMatchEvalBinByBin) {
  constexpr int kC = 8, kP = 8, kBins = kC * kP;
  auto bin = [&](const Vec3& w) {
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0) phi += 2 * M_PI;
    return std::clamp(int(w.z * kC), 0, kC - 1) * kP + std::clamp(int(phi / (2 * M_PI) * kP), 0, kP - 1);
  };
  for (const Material& m : {coated_diffuse(0.15f, Vec3(0.6f)), coated_gold(0.5f), coated_diffuse(0.0f, Vec3(0.8f))}) {
    const LayeredBxdf bsdf = consistent_lobe(m);
    const Vec3 wo = at_mu(0.5);
    const int n = 300000;
    std::vector<double> a(kBins, 0), a2(kBins, 0), b(kBins, 0), b2(kBins, 0);
    Rng rng(5);
    for (int i = 0; i < n; ++i) {
      BsdfSample s;
      float u1 = uniform_float(rng), u2 = uniform_float(rng), uc = uniform_float(rng);
      if (bsdf.sample(wo, u1, u2, uc, &s, uint64_t(i)) && !s.delta) {
        int j = bin(s.wi);
        a[j] += s.weight[1], a2[j] += double(s.weight[1]) * s.weight[1];
      }
      Vec3 wi = cosine_direction(rng);
      double v = bsdf.eval(wo, wi, uint64_t(i) + 1000000007ull)[1] * kPi;
      int j = bin(wi);
      b[j] += v, b2[j] += v * v;
    }
    double chi2 = 0;
    for (int j = 0; j < kBins; ++j) {
      double ma = a[j] / n, mb = b[j] / n;
      double var = (a2[j] / n - ma * ma) / n + (b2[j] / n - mb * mb) / n;
      if (var > 0) chi2 += (ma - mb) * (ma - mb) / var;
    }
    std::printf("%s: chi-square %.1f over %d bins\n", m.name.c_str(), chi2, kBins);
    EXPECT_LT(chi2, kBins + 5 * std::sqrt(2.0 * kBins)) << m.name << " roughness " << m.roughness;
  }
}

// (b) pbrt-v4's pdf estimate for a smooth coat over a Lambertian base is deterministic:
// 0.1 / (4 pi) + 0.9 cos(theta_t(wi)) / pi, theta_t the refracted angle of wi. Its integral over
// the sphere is then 0.1 + 0.9 x the integral of cos theta_t / pi, measured and printed; for a
// rough coat the estimate adds the entrance reflection's full pdf (pbrt-v4 samples it with the
// Reflection flag) and need not integrate to 1: MIS only needs it positive where f is.
TEST(LayeredBxdf, PdfIsPbrtsMixtureWithAUniformLobe) {
  Bsdf smooth(coated_diffuse(0.0f, Vec3(0.5f)));
  Rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    Vec3 wo = cosine_direction(rng), wi = cosine_direction(rng);
    double sin_t = std::sqrt(std::max(0.0, 1.0 - double(wi.z) * wi.z)) / 1.5;
    double expect = 0.1 / (4 * M_PI) + 0.9 * std::sqrt(1 - sin_t * sin_t) / M_PI;
    ASSERT_NEAR(smooth.pdf(wo, wi, uint64_t(i)), expect, 1e-5 * expect);
    ASSERT_NEAR(smooth.pdf(wo, Vec3{wi.x, wi.y, -wi.z}, uint64_t(i)), 0.1 / (4 * M_PI), 1e-9);
  }
  for (const Material& m : {coated_diffuse(0.0f, Vec3(0.5f)), coated_diffuse(0.15f, Vec3(0.5f)), coated_gold(0.5f)}) {
    Bsdf bsdf(m);
    const Vec3 wo = at_mu(0.6);
    Rng r2(9);
    Mean integral = average(200000, [&](int i) {
      Vec3 wi = cosine_direction(r2);
      float p = bsdf.pdf(wo, wi, uint64_t(i));
      EXPECT_GT(p, 0.0f);
      return Vec3(p * kPi / wi.z);
    });
    std::printf("%s: pdf integrates to %.3f over the upper hemisphere (+ 0.05 below)\n", m.name.c_str(),
                integral.mean[0]);
    EXPECT_GT(integral.mean[0], 0.4);
  }
}

// (c) Reciprocity in expectation: the mean of f(wo, wi) over 40000 keys equals that of
// f(wi, wo) within 4 standard errors and 1 % (with f()'s exit weighted consistently; pbrt-v4's
// weighting breaks it by up to 6 % at pbrt roughness 0.15); and no case reflects more than it
// receives.
TEST(LayeredBxdf, IsReciprocalAndConservesEnergyOnAverage) {
  const Vec3 pairs[][2] = {
      {at_mu(0.3, 0.2), at_mu(0.8, 2.0)}, {at_mu(0.9, 1.0), at_mu(0.5, 4.0)}, {at_mu(0.4, 0.0), at_mu(0.45, 3.0)}};
  for (const Material& m : {coated_diffuse(0.15f, Vec3(0.2f, 0.5f, 0.8f)), coated_diffuse(0.5f, Vec3(0.9f)),
                            coated_gold(0.15f), coated_diffuse(0.0f, Vec3(0.7f))}) {
    const LayeredBxdf bsdf = consistent_lobe(m);
    for (const auto& p : pairs) {
      Mean ab = average(40000, [&](int i) { return bsdf.eval(p[0], p[1], uint64_t(i)); });
      Mean ba = average(40000, [&](int i) { return bsdf.eval(p[1], p[0], uint64_t(i) + 777777); });
      for (int k = 0; k < 3; ++k) {
        double tol = 4 * std::hypot(ab.se[k], ba.se[k]) + 0.01 * ab.mean[k];
        EXPECT_NEAR(ab.mean[k], ba.mean[k], tol) << m.name << " roughness " << m.roughness << " channel " << k;
      }
    }
  }
  for (const FurnaceCase& fc : furnace_cases())
    for (double mu : {0.1, 0.5, 1.0}) {
      Mean a = analog_albedo(fc.m, at_mu(mu), 2, 100000);
      for (int k = 0; k < 3; ++k) EXPECT_LE(a.mean[k], 1.0 + 3 * a.se[k]) << fc.name;
    }
}

// Ray from the camera through film point (fx, fy) to the unit sphere at `centre`: the cosine
// between the normal and the direction back to the camera (0 on a miss).
double mu_at(const ThinLensCamera& cam, float fx, float fy, const Vec3& centre) {
  Ray r = cam.generate(fx, fy, {0.5, 0.5}, 0);
  Vec3 oc = r.org - centre, d = normalize(r.dir);
  double b = dot(oc, d), c = dot(oc, oc) - 1.0, disc = b * b - c;
  if (disc < 0) return 0;
  Vec3 p = r.org + d * float(-b - std::sqrt(disc));
  return std::max(0.0f, -dot(normalize(p - centre), d));
}

// (d) A rendered sphere of coated_diffuse (reflectance 0.8, pbrt-v4 roughness 0, 0.15, 0.5)
// in a white environment: the mean of the pixels inside 0.8 of the silhouette equals the
// analog particle's albedo averaged over the same pixels' viewing angles, within 1 %, with
// f()'s exit weighted consistently. As pbrt-v4 weighs it (the default) the render is brighter
// where light sampling carries the estimate: printed, +0.7 % and +0.9 % at roughness 0.15 and
// 0.5, below 3 %. The renders are the mean of four seeds: the random walks have a heavy tail,
// and on a machine without AVX-512 (Embree takes another code path, so other paths) seed 7
// alone read +1.2 % at roughness 0.5, seven other seeds -0.8 to +0.2 %.
TEST(LayeredBxdf, RenderedFurnaceSphereMatchesTheAnalogExpectation) {
  for (float r : {0.0f, 0.15f, 0.5f}) {
    const Vec3 centre(2, -1, 10);
    Material m = coated_diffuse(r, Vec3(0.8f));
    SceneDesc pbrt = furnace_sphere(24, 24, 256, centre, m);
    pbrt.integrator.max_depth = 8;
    m.layers.consistent_exit = true;
    SceneDesc s = furnace_sphere(24, 24, 256, centre, m);
    s.integrator.max_depth = 8;
    constexpr uint64_t kSeeds[] = {7, 1, 2, 3};
    std::vector<Image> im, im_pbrt;
    for (uint64_t seed : kSeeds) {
      s.sampler.seed = pbrt.sampler.seed = seed;
      im.push_back(render_quietly(s).image), im_pbrt.push_back(render_quietly(pbrt).image);
    }
    ThinLensCamera cam(s.camera, s.film.width, s.film.height);
    const Slab slab = slab_of(m);
    Rng rng(41);
    double sum = 0, sum_pbrt = 0, expect = 0;
    const auto px = pixels_inside_silhouette(s, centre, 0.8);
    ASSERT_GT(px.size(), 60u);
    for (auto [x, y] : px) {
      for (std::size_t k = 0; k < im.size(); ++k)
        sum += mean_rgb(im[k], x, y) / double(im.size()), sum_pbrt += mean_rgb(im_pbrt[k], x, y) / double(im.size());
      const int k = 8000;
      double e = 0;
      for (int i = 0; i < k; ++i) {
        double mu = mu_at(cam, float(x + rng.uniform()), float(y + rng.uniform()), centre);
        e += analog_particle(slab, at_mu(mu, 2 * M_PI * rng.uniform()), rng)[0];
      }
      expect += e / k;
    }
    sum /= double(px.size()), sum_pbrt /= double(px.size()), expect /= double(px.size());
    std::printf("coated_diffuse layered, pbrt roughness %.2f: rendered %.4f (pbrt-v4's weighting %.4f), analog %.4f\n",
                r, sum, sum_pbrt, expect);
    EXPECT_NEAR(sum, expect, 0.01 * expect) << "pbrt roughness " << r;
    EXPECT_NEAR(sum_pbrt, expect, 0.03 * expect) << "pbrt roughness " << r;
  }
}

// (e) Replayable: the random walks draw from keys of (seed, pixel, sample index, vertex), so
// a scene of layered materials renders bit for bit the same at 1 and 2 threads.
TEST(LayeredBxdf, ImagesAreTheSameAtOneAndTwoThreads) {
  const Vec3 centre(0, 0, 0);
  SceneDesc s = furnace_sphere(20, 20, 8, centre, coated_diffuse(0.15f, Vec3(0.3f, 0.6f, 0.9f)));
  s.shapes.push_back(sphere(centre + Vec3(0.9f, 0.6f, 0.5f), 0.4f, add_material(s, coated_gold(0.5f))));
  Image a = render_quietly(s, 1).image, b = render_quietly(s, 2).image;
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  EXPECT_TRUE(a.rgb == b.rgb);
}

}  // namespace
}  // namespace pdrt
