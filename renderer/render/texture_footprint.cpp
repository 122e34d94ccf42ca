#include "renderer/render/texture_footprint.h"

#include "renderer/render/screen_window.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

TextureFootprint::TextureFootprint(const CameraDesc& c, int film_width, int film_height, int spp) {
  eye_ = c.position;
  forward_ = normalize(c.look_at - c.position);
  right_ = normalize(cross(forward_, c.up));
  up_ = cross(right_, forward_);
  ortho_ = c.projection == CameraDesc::Projection::Orthographic;
  const std::array<float, 4> w = screen_window(c, std::max(film_width, 1), std::max(film_height, 1));
  const float scale = std::max(0.125f, 1.0f / std::sqrt(float(std::max(spp, 1))));
  pixel_x_ = (w[1] - w[0]) / float(std::max(film_width, 1)) * scale;
  pixel_ = (w[3] - w[2]) / float(std::max(film_height, 1)) * scale;
}

TextureCoords TextureFootprint::at(const SurfaceHit& hit) const {
  TextureCoords tc;
  tc.u = hit.u, tc.v = hit.v;
  const Vec3 d = hit.p - eye_;
  const float depth = dot(d, forward_);
  const Vec3 n = hit.ng;
  const float nd = dot(n, d);
  // The neighbouring pixel's ray d + pixel * depth * axis meets the tangent plane at
  // eye + t (d + ...), t = n.d / n.(d + ...): its offset from p is dp/dx (or dp/dy).
  // Orthographic: the neighbour's ray is parallel, pixel * axis to the side; it meets the
  // plane pixel * axis - forward n.(pixel * axis) / n.forward from p.
  auto offset = [&](const Vec3& axis, float pixel) {
    if (ortho_) {
      const Vec3 side = axis * pixel;
      const float den = dot(n, forward_);
      const Vec3 dp = side - forward_ * (dot(n, side) / den);
      return is_finite(dp) && den != 0 ? dp : Vec3(0.0f);
    }
    const Vec3 dn = d + axis * (pixel * depth);
    const float den = dot(n, dn);
    const Vec3 dp = dn * (nd / den) - d;
    return is_finite(dp) && den != 0 ? dp : Vec3(0.0f);
  };
  const Vec3 dpdx = offset(right_, pixel_x_), dpdy = offset(up_, pixel_);
  // Least squares (pbrt-v4 SurfaceInteraction::ComputeDifferentials).
  const float a00 = dot(hit.dpdu, hit.dpdu), a01 = dot(hit.dpdu, hit.dpdv), a11 = dot(hit.dpdv, hit.dpdv);
  const float det = a00 * a11 - a01 * a01;
  if (!(std::abs(det) > 0) || !std::isfinite(det)) return tc;
  const float inv = 1 / det;
  const float bx0 = dot(hit.dpdu, dpdx), bx1 = dot(hit.dpdv, dpdx);
  const float by0 = dot(hit.dpdu, dpdy), by1 = dot(hit.dpdv, dpdy);
  auto tame = [](float x) { return std::isfinite(x) ? std::clamp(x, -1e8f, 1e8f) : 0.0f; };
  tc.dudx = tame((a11 * bx0 - a01 * bx1) * inv);
  tc.dvdx = tame((a00 * bx1 - a01 * bx0) * inv);
  tc.dudy = tame((a11 * by0 - a01 * by1) * inv);
  tc.dvdy = tame((a00 * by1 - a01 * by0) * inv);
  return tc;
}

}  // namespace pdrt
