// Russian roulette must not add noise where the path throughput does not fall: inside a
// lossless dielectric the radiance is only compressed by 1/eta^2, which pbrt-v4's etaScale
// removes from the survival probability.
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace pdrt;
using namespace pdrt::test;

// A smooth glass sphere (ior 1.5) in a white furnace reads exactly 1 with zero variance:
// every path leaves the sphere with throughput 1. Checked pixel by pixel well inside the
// silhouette (where internal reflections stay far below max_depth), with roulette from the
// first vertex on and at the default depth, at 1, 2, 4 and 16 spp, for every sampler, with
// the sphere away from the origin.
TEST(RussianRoulette, SmoothGlassSphereInAFurnaceIsNoiseFree) {
  const int W = 24, H = 24;
  const Vec3 centre(-300, 40, 1e3f);
  for (const char* sampler : {"random", "jitter", "poisson", "sobol"})
    for (int rr_depth : {1, 3})
      for (int spp : {1, 2, 4, 16}) {
        SceneDesc s = furnace_sphere(W, H, spp, centre, glass(1.5f));
        s.sampler.type = sampler;
        s.integrator.max_depth = 64, s.integrator.rr_depth = rr_depth;
        Image im = render_quietly(s).image;
        double worst = 0;
        int n = 0;
        for (auto [x, y] : pixels_inside_silhouette(s, centre, 0.7)) {
          const std::size_t i = 3 * (std::size_t(y) * W + x);
          for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(im.rgb[i + c]) - 1.0));
          ++n;
        }
        ASSERT_GT(n, 20);
        EXPECT_LT(worst, 1e-3) << sampler << " rr_depth " << rr_depth << " spp " << spp << " over " << n << " pixels";
      }
}

// The same furnace at 1024 spp with the default depth (8) and roulette (from 3), on a small
// film: the mean over the pixels inside the silhouette is within 3 standard errors (over
// those pixels) of its value for `random`, for every sampler. Before issue 15, poisson read
// 0.9985, 18 standard errors low: the lobe choices of one path shared Poisson tables.
TEST(RussianRoulette, SmoothGlassSphereInAFurnaceAt1024SppAgreesAcrossSamplers) {
  const int W = 8, H = 8;
  const Vec3 centre(0, 0, 0);
  auto reading = [&](const char* sampler) {
    SceneDesc s = furnace_sphere(W, H, 1024, centre, glass(1.5f));
    s.sampler.type = sampler;
    Image im = render_quietly(s).image;
    double sum = 0, sum2 = 0;
    int n = 0;
    for (auto [x, y] : pixels_inside_silhouette(s, centre, 0.9)) {
      const std::size_t i = 3 * (std::size_t(y) * W + x);
      const double v = (double(im.rgb[i]) + im.rgb[i + 1] + im.rgb[i + 2]) / 3;
      sum += v, sum2 += v * v, ++n;
    }
    const double mean = sum / n;
    return std::pair{mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
  };
  const auto [ref, ref_se] = reading("random");
  for (const char* sampler : {"jitter", "poisson", "sobol"}) {
    const auto [mean, se] = reading(sampler);
    std::printf("furnace 1024 spp: %s %.5f +- %.5f (random %.5f +- %.5f)\n", sampler, mean, se, ref, ref_se);
    EXPECT_NEAR(mean, ref, 3 * std::hypot(se, ref_se)) << sampler;
  }
}
