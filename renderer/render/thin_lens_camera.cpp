#include "renderer/render/thin_lens_camera.h"

#include "renderer/render/concentric_disk.h"
#include "renderer/render/screen_window.h"

#include <cmath>

namespace pdrt {

namespace {

Vec3 eye_at(const CameraDesc& d, float shutter_time, Vec3* look_at) {
  if (d.motion.empty()) {
    *look_at = d.look_at;
    return d.position;
  }
  const auto& k = d.motion;
  if (shutter_time <= k.front().time) return *look_at = k.front().look_at, k.front().position;
  if (shutter_time >= k.back().time) return *look_at = k.back().look_at, k.back().position;
  std::size_t i = 0;
  while (i + 2 < k.size() && k[i + 1].time <= shutter_time) ++i;
  float t = (shutter_time - k[i].time) / (k[i + 1].time - k[i].time);
  *look_at = lerp(t, k[i].look_at, k[i + 1].look_at);
  return lerp(t, k[i].position, k[i + 1].position);
}

}  // namespace

ThinLensCamera::ThinLensCamera(const CameraDesc& desc, int width, int height) : desc_(desc) {
  ortho_ = desc.projection == CameraDesc::Projection::Orthographic;
  const std::array<float, 4> w = screen_window(desc, width, height);
  x0_ = w[0], y1_ = w[3];
  sx_scale_ = (w[1] - w[0]) / float(width), sy_scale_ = (w[3] - w[2]) / float(height);
  if (desc_.focus_distance <= 0) desc_.focus_distance = length(desc.look_at - desc.position);
  static_pose_ = pose_at(0.0f);
}

ThinLensCamera::Pose ThinLensCamera::pose_at(float time) const {
  float shutter_time = desc_.shutter_open + time * (desc_.shutter_close - desc_.shutter_open);
  Vec3 look;
  Pose p;
  p.eye = eye_at(desc_, shutter_time, &look);
  p.forward = normalize(look - p.eye);
  p.right = normalize(cross(p.forward, desc_.up));
  p.up = cross(p.right, p.forward);
  if (desc_.flip_x) p.right = -p.right;
  return p;
}

std::array<float, 2> ThinLensCamera::aperture_point(std::array<double, 2> u, int blades, float rotation) {
  if (blades < 3) {
    auto [r, phi] = concentric_disk_polar(u);
    return {r * std::cos(phi + rotation), r * std::sin(phi + rotation)};
  }
  // Regular polygon inscribed in the unit circle: pick a wedge with u0, then a uniform point in
  // the wedge triangle (sqrt for the radial coordinate keeps density uniform).
  double w = u[0] * blades;
  int k = std::min(int(w), blades - 1);
  float s = float(w - k), t = float(u[1]);
  float a0 = rotation + 2 * kPi * k / blades, a1 = rotation + 2 * kPi * (k + 1) / blades;
  float r = std::sqrt(t);
  float x = r * ((1 - s) * std::cos(a0) + s * std::cos(a1));
  float y = r * ((1 - s) * std::sin(a0) + s * std::sin(a1));
  return {x, y};
}

Ray ThinLensCamera::generate(float film_x, float film_y, std::array<double, 2> lens_u, float time) const {
  Pose moving;  // a reference to the static pose otherwise: copying it costs more than the ray
  const Pose& p = desc_.motion.empty() ? static_pose_ : (moving = pose_at(time));
  const float sx = x0_ + film_x * sx_scale_, sy = y1_ - film_y * sy_scale_;
  if (ortho_) return generate_parallel(p, sx, sy, lens_u, time);
  Ray ray;
  ray.time = time;
  Vec3 d = p.forward + p.right * sx + p.up * sy;  // direction through the pixel, forward component 1
  if (desc_.aperture_radius <= 0) {
    ray.org = p.eye;
    ray.dir = normalize(d);
    return ray;
  }
  Vec3 focus = p.eye + d * desc_.focus_distance;  // on the plane of focus
  auto a = aperture_point(lens_u, desc_.aperture_blades, desc_.aperture_rotation_deg * kPi / 180.0f);
  ray.org = p.eye + p.right * (a[0] * desc_.aperture_radius) + p.up * (a[1] * desc_.aperture_radius);
  ray.dir = normalize(focus - ray.org);
  return ray;
}

// pbrt-v4 OrthographicCamera::GenerateRay: the pixel's point on the screen window, moved by
// the lens offset, aimed at where the unmoved ray meets the plane of focus.
Ray ThinLensCamera::generate_parallel(const Pose& p, float sx, float sy, std::array<double, 2> lens_u,
                                      float time) const {
  const Vec3 o = p.eye + p.right * sx + p.up * sy;
  Ray ray;
  ray.time = time;
  if (desc_.aperture_radius <= 0) {
    ray.org = o;
    ray.dir = p.forward;
    return ray;
  }
  const Vec3 focus = o + p.forward * desc_.focus_distance;
  auto a = aperture_point(lens_u, desc_.aperture_blades, desc_.aperture_rotation_deg * kPi / 180.0f);
  ray.org = o + p.right * (a[0] * desc_.aperture_radius) + p.up * (a[1] * desc_.aperture_radius);
  ray.dir = normalize(focus - ray.org);
  return ray;
}

std::array<float, 2> ThinLensCamera::project(const Vec3& w) const {
  const Pose& p = static_pose_;
  Vec3 v = w - p.eye;
  float sx = dot(v, p.right), sy = dot(v, p.up);
  if (!ortho_) {
    const float z = dot(v, p.forward);
    sx /= z, sy /= z;
  }
  return {(sx - x0_) / sx_scale_, (y1_ - sy) / sy_scale_};
}

}  // namespace pdrt
