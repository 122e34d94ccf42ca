#include "renderer/assetgen/procedural_sky.h"

#include "renderer/scene/equirect.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace {

Vec3 sky_radiance(const SkyParams& p, const Vec3& d) {
  const float cos_sun = std::clamp(dot(d, p.to_sun), -1.0f, 1.0f);
  const float gamma = std::acos(cos_sun);  // angle to the sun
  const float r = p.sun_radius_deg * kPi / 180;
  if (gamma < r) {
    // Limb darkening (the Sun's, roughly): 1 - 0.6 (1 - mu), mu the cosine on the disc.
    const float s = gamma / r, mu = std::sqrt(std::max(0.0f, 1 - s * s));
    return p.sun_radiance * (1 - 0.6f * (1 - mu));
  }
  if (d.y < 0) {
    // Ground, with a little haze fading in over the first degrees below the horizon.
    const float haze = std::exp(-(-d.y) * 30);
    return p.ground * (1 - haze) + p.horizon * (0.6f * haze);
  }
  const float t = std::exp(-4 * d.y);  // 1 at the horizon, e^-4 at the zenith
  const Vec3 base = p.zenith * (1 - t) + p.horizon * t;
  const Vec3 glow =
      p.aureole * (0.6f * std::exp(-gamma * gamma / (2 * 0.12f * 0.12f)) + 0.15f * std::exp(-gamma / 0.6f));
  return base + glow;
}

}  // namespace

std::vector<float> procedural_sky(const SkyParams& p) {
  constexpr int kSub = 4;
  std::vector<float> rgb(std::size_t(p.width) * p.height * 3);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      Vec3 sum(0.0f);
      for (int sy = 0; sy < kSub; ++sy)
        for (int sx = 0; sx < kSub; ++sx) {
          const double u = (x + (sx + 0.5) / kSub) / p.width, v = (y + (sy + 0.5) / kSub) / p.height;
          sum += sky_radiance(p, equirect_direction(u, v));
        }
      const Vec3 c = sum / float(kSub * kSub);
      float* o = &rgb[3 * (std::size_t(y) * p.width + x)];
      o[0] = c.x, o[1] = c.y, o[2] = c.z;
    }
  return rgb;
}

}  // namespace pdrt
