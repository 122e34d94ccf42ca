#pragma once
// The image-plane pattern of `poisson-ip` (issue 31 item 2): one hierarchical Poisson-disk
// pattern on the unit torus whose period spans many pixels, as McCool & Fiume §3 ask ("the
// period should be much larger than the pixel size"). McCool–Fiume relaxation dart throwing
// (§4, generator `mccool`, periodic): points in generation order, every prefix Poisson-disk at
// the radius in force when its last point was placed, so the prefix of spp * P^2 points, scaled
// to P x P pixels, is a Poisson-disk set of spp points per pixel area across pixel borders and
// across the period's wrap.
#include <cstdint>
#include <vector>

namespace pdrt {

// Points of the pattern: enough for a period of 256 x 256 pixels at 1 spp, 64 x 64 at 16 spp.
inline constexpr int64_t kImagePlanePoints = int64_t(1) << 16;

struct ImagePlanePattern {
  std::vector<uint32_t> coords;  // point i at (coords[2i], coords[2i + 1]), 32-bit fixed point
  std::vector<float> radius;     // the minimum distance in force when point i was placed
  int64_t size() const { return int64_t(radius.size()); }
};

// The pattern, generated deterministically on first use (about 1 s of CPU) and kept in the
// cache directory (sampling/core/cache_dir.h) for later runs.
const ImagePlanePattern& image_plane_pattern();

// The period, in pixels, for `spp` samples per pixel: the largest P with spp * P^2 <= the
// pattern's points, so that the render takes a prefix of spp * P^2 points; 0 when spp exceeds
// the points (no period fits).
int image_plane_period(int64_t spp);

}  // namespace pdrt
