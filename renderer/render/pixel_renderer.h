#pragma once
// One pixel's samples, from camera ray to film: camera samples in packets of four, the path
// integrator, and the reconstruction that files each radiance in the film (its own pixel, or
// splatted over the filter's support, Cook §4.2).
#include "renderer/render/embree_scene.h"
#include "renderer/render/expected_splat_weight.h"
#include "renderer/render/film.h"
#include "renderer/render/filter.h"
#include "renderer/render/path_integrator.h"
#include "renderer/render/thin_lens_camera.h"

#include <cmath>
#include <cstdint>

namespace pdrt {

struct PixelRenderer {
  const ThinLensCamera& camera;
  const EmbreeScene& scene;
  const PathIntegrator& integrator;
  const Filter& filter;
  Reconstruction mode;
  int ox = 0, oy = 0;  // the film's pixel (0, 0) in image pixels (crop window)
  // Set when splatting a sampler whose pixels' counts vary (`poisson-ip`): a pixel's estimate
  // divides by spp times its expected weight (expected_splat_weight.h).
  const ExpectedSplatWeight* expected = nullptr;
  bool shutter = true;  // false: nothing moves (has_motion), so the shutter time is not drawn

  // Pixels beyond its own that a splatted sample can reach (film point in [x, x + 1)).
  int splat_margin() const { return int(std::ceil(filter.radius())) + 1; }

  // Samples [begin, end) of pixel (x, y) into `film`; returns rays traced. Camera rays go to
  // Embree as packets of four: always the samples [4j, 4j + 4), whatever [begin, end) is,
  // because packet and single-ray kernels may differ in the last bit; so a pixel's samples
  // are the same whether it is rendered at once or over adaptive rounds.
  // With `decide` (decision "split"), odd i go there and even i to `film`, as sample i >> 1
  // of two independent samplers (`pd` for the decision, seeded apart): each film gets a full
  // prefix of its own sampler, stratified as a whole, and the estimate's samples are
  // independent of the ones that chose when to stop. Each film's `halves` buffers split it by
  // the parity of i >> 1.
  // Under rank selection [begin, end) is a budget: every candidate of the larger prefix is
  // visited, and those kept now but not before are traced. So it is for a sampler whose
  // pixels' counts vary: the pixel traces its samples [samples_in_pixel(begin),
  // samples_in_pixel(end)).
  int64_t run(int x, int y, int64_t begin, int64_t end, Film& film, Film* decide, PixelSampleState& ps,
              PixelSampleState* pd) const;

  // Cook §4.2: the sample at film point (fx, fy) adds to every pixel whose filter covers it
  // (of those the film holds: under a crop window, none beyond the rendered rectangle).
  void splat(Film& film, float fx, float fy, const PathResult& pr, int half) const;
};

}  // namespace pdrt
