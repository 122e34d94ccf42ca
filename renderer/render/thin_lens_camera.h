#pragma once
// Cook §5.3 depth of field: a thin lens of radius `aperture_radius` focused at
// `focus_distance`. The ray through the pixel point from the lens centre fixes the focal
// point; rays from every lens point pass through it, so points at the focus distance stay
// sharp and others spread over the circle of confusion. Polygonal apertures (blades) give
// polygonal bokeh. Camera motion interpolates keyframed position / look-at over the shutter.
// Both of pbrt-v4's projective cameras (§5.2): perspective (rays from the eye through the
// screen window at distance 1) and orthographic (parallel rays from the screen window, lens
// offsets aimed at the point on the plane of focus, as pbrt-v4's OrthographicCamera).
#include "renderer/render/ray.h"
#include "renderer/scene/scene_desc.h"

#include <array>

namespace pdrt {

class ThinLensCamera {
 public:
  ThinLensCamera(const CameraDesc& desc, int width, int height);

  // Film point (x, y) in pixels from the top-left corner, lens sample in [0,1)^2, time in [0,1)
  // as a fraction of the shutter. Returns a ray with unit direction.
  Ray generate(float film_x, float film_y, std::array<double, 2> lens_u, float time) const;
  bool has_aperture() const { return desc_.aperture_radius > 0; }  // else generate() ignores lens_u

  // Maps a unit-square sample to a point on the aperture (unit disk or regular polygon),
  // uniformly by area.
  static std::array<float, 2> aperture_point(std::array<double, 2> u, int blades, float rotation_rad);

  // Pinhole (or parallel) projection at time 0: world point -> film pixel coordinates (for tests).
  std::array<float, 2> project(const Vec3& p) const;

 private:
  struct Pose {
    Vec3 eye, right, up, forward;  // right-handed: forward = look direction
  };
  Pose pose_at(float time) const;
  Ray generate_parallel(const Pose& p, float sx, float sy, std::array<double, 2> lens_u, float time) const;

  CameraDesc desc_;
  bool ortho_;
  // Film point -> screen window: sx = x0 + film_x * sx_scale, sy = y1 - film_y * sy_scale.
  float x0_, y1_, sx_scale_, sy_scale_;
  Pose static_pose_;
};

}  // namespace pdrt
