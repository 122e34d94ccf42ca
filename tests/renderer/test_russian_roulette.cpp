// Russian roulette must not add noise where the path throughput does not fall: inside a
// lossless dielectric the radiance is only compressed by 1/eta^2, which pbrt-v4's etaScale
// removes from the survival probability.
#include "renderer/render/thin_lens_camera.h"
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
        SceneDesc s = base_scene(W, H, spp);
        s.sampler.type = sampler;
        s.integrator.max_depth = 64, s.integrator.rr_depth = rr_depth;
        s.camera.position = centre + Vec3(0, 0, 4), s.camera.look_at = centre, s.camera.vfov_deg = 30;
        s.environment.radiance = Vec3(1.0f);
        s.shapes.push_back(sphere(centre, 1, add_material(s, glass(1.5f))));
        Image im = render_quietly(s).image;
        ThinLensCamera cam(s.camera, W, H);
        const double rad = 0.7 * (cam.project(centre + Vec3(0.5f, 0, 1))[0] - W / 2.0);
        double worst = 0;
        int n = 0;
        for (int y = 0; y < H; ++y)
          for (int x = 0; x < W; ++x) {
            const double dx = x + 0.5 - W / 2.0, dy = y + 0.5 - H / 2.0;
            if (dx * dx + dy * dy > rad * rad) continue;
            const std::size_t i = 3 * (std::size_t(y) * W + x);
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(im.rgb[i + c]) - 1.0));
            ++n;
          }
        ASSERT_GT(n, 20);
        EXPECT_LT(worst, 1e-3) << sampler << " rr_depth " << rr_depth << " spp " << spp << " over " << n << " pixels";
      }
}
