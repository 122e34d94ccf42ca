// TilePasses::work, the samples a pass would add (the progress line's total and the ETA's
// trusted work): it counts what the calibration's blocks already hold, and reads the films
// only in tiles that may hold samples.
#include "renderer/render/embree_scene.h"
#include "renderer/render/filter.h"
#include "renderer/render/light_set.h"
#include "renderer/render/path_integrator.h"
#include "renderer/render/pixel_renderer.h"
#include "renderer/render/process_group.h"
#include "renderer/render/render_films.h"
#include "renderer/render/thin_lens_camera.h"
#include "renderer/render/tile_passes.h"
#include "renderer/render/tile_waves.h"
#include "sampling/core/progress.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

#include <chrono>

namespace pdrt {
namespace {

TEST(TilePasses, WorkCountsTheCalibratedBlocksSamplesAsTakenAndAPassTakesTheRest) {
  constexpr int kW = 40, kH = 24;  // 3 x 2 tiles of 16, the last column and row partial
  const SceneDesc desc = test::furnace_sphere(kW, kH, 8, Vec3(0), test::diffuse(0.5f));
  EmbreeDevice device;
  EmbreeScene scene(desc, device);
  MaterialSet materials(scene, TextureFootprint(desc.camera, kW, kH, 8), desc.integrator.regularize);
  LightSet lights(scene, materials.textures());
  PathIntegrator integrator(scene, lights, materials, desc.integrator);
  ThinLensCamera camera(desc.camera, kW, kH);
  Filter filter(desc.film.filter);
  RenderFilms films(kW, kH, false);
  const PixelRenderer pixels{camera, scene, integrator, filter, desc.film.filter.reconstruction, 0, 0, nullptr, false};
  const auto sampler = make_sampler("poisson", 3);
  const LocalProcessGroup alone;
  const RenderOptions opt;
  const TileWaves tiles(kW, kH, PixelRect{0, kW, 0, kH}, 0);
  TilePasses passes(tiles, films, pixels, *sampler, nullptr, alone, opt, std::chrono::steady_clock::now());
  const auto to = [](int64_t n) { return [n](int, int) { return n; }; };

  EXPECT_EQ(passes.work(to(8)), double(kW * kH * 8));
  // Two 4 x 4 blocks in two tiles (the second in the partial corner tile) take 4 samples each.
  const std::vector<PixelRect> blocks{{20, 24, 3, 7}, {33, 37, 17, 21}};
  passes.calibrate(blocks, 0, 2, 4);
  for (const PixelRect& b : blocks)
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0; x < b.x1; ++x) ASSERT_EQ(films.image.at(x, y).prefix, 4);
  EXPECT_EQ(passes.work(to(8)), double(kW * kH * 8 - 32 * 4));
  EXPECT_EQ(passes.work(to(2)), double((kW * kH - 32) * 2));  // no pixel gives samples back
  EXPECT_EQ(passes.work([](int x, int y) { return int64_t(x == 21 && y == 4 ? 6 : 0); }), 2.0);

  Progress progress("test", passes.work(to(8)), true);
  ASSERT_TRUE(passes.run(to(8), progress));
  EXPECT_EQ(passes.work(to(8)), 0.0);
  EXPECT_EQ(passes.work(to(16)), double(kW * kH * 8));
}

}  // namespace
}  // namespace pdrt
