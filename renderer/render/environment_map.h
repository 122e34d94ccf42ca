#pragma once
// An image-based environment light (pbrt-v3 §14.2.4, pbrt-v4's ImageInfiniteLight): an
// equirectangular image (equirect.h) of linear RGB radiance, times a per-channel scale,
// turned about +y. Radiance is the bilinear interpolation of the texels (centres at
// ((i + 0.5) / width, (j + 0.5) / height); u wraps, v clamps at the poles), so a texel
// centre returns the texel.
//
// Directions are importance sampled by a piecewise-constant 2-D distribution over the
// texel grid: cell (i, j) holds the mean over the cell of the interpolated luminance (the
// 3 x 3 texels around it, weights 1/8, 6/8, 1/8 per axis) times sin(theta) at the row's
// centre. The mean, not the texel, because the interpolation spreads a texel over its
// neighbours' cells: every direction of non-zero radiance then has a non-zero pdf, and light
// sampling alone stays an unbiased estimator. pdf(w) = p(u, v) / (2 pi^2 sin theta), the
// exact density of sample().
//
// Compensated sampling (EnvironmentSampling::Compensated, pbrt-v4's allowIncompletePDF) uses
// max(cell mean - the map's solid-angle mean, 0) instead (Karlik et al. 2019, "MIS
// compensation"): directions dimmer than average get pdf 0 and are left to BSDF sampling,
// so it is only valid under MIS with a BSDF that can reach them. A constant map, with
// nothing above its mean, is sampled uniformly over the sphere, as pbrt-v4 does.
#include "renderer/scene/settings_names.h"
#include "renderer/scene/vec3.h"
#include "sampling/core/piecewise_constant.h"

#include <array>
#include <vector>

namespace pdrt {

class EnvironmentMap {
 public:
  EnvironmentMap() = default;
  // `rgb`: width * height linear RGB, top row first, finite and >= 0.
  EnvironmentMap(int width, int height, std::vector<float> rgb, Vec3 scale, float rotation_deg,
                 EnvironmentSampling sampling = EnvironmentSampling::Full);

  bool empty() const { return width_ == 0; }
  // Radiance arriving from the world direction w (unit).
  Vec3 radiance(const Vec3& w) const;
  // A direction for the light-family pair u, its radiance and solid-angle pdf; false for
  // the measure-zero samples at the poles.
  bool sample(std::array<double, 2> u, Vec3* wi, Vec3* radiance, float* pdf) const;
  float pdf(const Vec3& w) const;
  // The light-selection importance in the BVH's units (irradiance): pi times the
  // solid-angle mean of the luminance, what a constant environment of that luminance
  // delivers to a surface (pi L).
  float irradiance_estimate() const { return irradiance_; }

  // World direction <-> the map's (u, v) (equirect.h, then the rotation).
  Vec3 direction(double u, double v) const;
  std::array<double, 2> uv(const Vec3& w) const;
  // Scaled radiance at the image point (u, v), bilinear.
  Vec3 lookup(double u, double v) const;

 private:
  Vec3 texel(int x, int y) const;                            // scaled; x wraps, y clamps
  static float solid_angle_pdf(double p_uv, const Vec3& w);  // p(u, v) / (2 pi^2 sin theta)

  int width_ = 0, height_ = 0;
  std::vector<float> rgb_;
  Vec3 scale_{1.0f};
  float cos_r_ = 1, sin_r_ = 0;
  PiecewiseConstant2D distribution_;  // over [0, 1]^2 in (u, v)
  float irradiance_ = 0;
};

}  // namespace pdrt
