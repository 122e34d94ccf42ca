#pragma once
// The procedural HDR sky pdrt generates at build time (no image can be downloaded): an
// equirectangular image (scene/equirect.h) of linear RGB radiance with a blue gradient from
// zenith to a pale horizon, an aureole around the sun, a small, very bright sun disc with
// limb darkening, and a dim ground below the horizon. An analytic stand-in for a measured
// sky, not a physical model: the zenith/horizon blend follows the exponential falloff of
// Preetham et al. 1999's luminance distribution, the aureole a Gaussian in the angle to the
// sun. Pure float arithmetic on the texel grid, 4 x 4 samples per texel: the same pixels
// on every run.
#include "renderer/scene/vec3.h"

#include <vector>

namespace pdrt {

struct SkyParams {
  int width = 512, height = 256;
  Vec3 to_sun = normalize(Vec3(-0.55f, 0.62f, 0.56f));  // unit, in the map's frame
  float sun_radius_deg = 2.5f;                          // wider than the real 0.27 degrees: soft shadow edges
  Vec3 sun_radiance{900.0f, 830.0f, 720.0f};
  Vec3 zenith{0.06f, 0.12f, 0.34f}, horizon{0.38f, 0.47f, 0.62f}, ground{0.12f, 0.11f, 0.1f};
  Vec3 aureole{0.9f, 0.75f, 0.5f};
};

// width * height RGB, top row first.
std::vector<float> procedural_sky(const SkyParams& p = {});

}  // namespace pdrt
