#pragma once
// pbrt-v4's environment images: the sphere on a square by Clarberg's equal-area octahedral
// map ("Fast Equal-Area Mapping of the (Hemi)Sphere using SIMD", 2008; pbrt-v4 §3.8.3). The
// upper hemisphere (+z) fills the inner diamond, the lower one the four corners; every texel
// covers the same solid angle. pdrt's environment light reads equirectangular images
// (renderer/scene/equirect.h), so the importer resamples.
#include "renderer/scene/environment_image.h"
#include "renderer/scene/vec3.h"

#include <array>
#include <functional>

namespace pdrt {

// (u, v) in [0, 1]^2 to the unit direction, and back.
Vec3 equal_area_square_to_sphere(double u, double v);
std::array<double, 2> equal_area_sphere_to_square(const Vec3& d);

// The square image `src` (pbrt-v4's layout: row 0 is v = 0) as an equirectangular image of
// 2n x n texels for an n x n source: each texel is the mean of 2 x 2 bilinear lookups, with
// pbrt-v4's octahedral wrap across the square's edges. `to_light` takes a world direction
// (pdrt's equirect convention) to the light's own space, in which the square is defined.
EnvironmentImage octahedral_to_equirect(const EnvironmentImage& src, const std::function<Vec3(const Vec3&)>& to_light);

}  // namespace pdrt
