#include "renderer/scene/pbrt/pbrt_matrix.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

Mat4 Mat4::translate(double x, double y, double z) {
  Mat4 r;
  r.m[0][3] = x, r.m[1][3] = y, r.m[2][3] = z;
  return r;
}

Mat4 Mat4::scale(double x, double y, double z) {
  Mat4 r;
  r.m[0][0] = x, r.m[1][1] = y, r.m[2][2] = z;
  return r;
}

Mat4 Mat4::rotate(double degrees, double x, double y, double z) {
  const double len = std::sqrt(x * x + y * y + z * z);
  x /= len, y /= len, z /= len;
  const double t = degrees * M_PI / 180, s = std::sin(t), c = std::cos(t);
  Mat4 r;
  r.m[0] = {x * x + (1 - x * x) * c, x * y * (1 - c) - z * s, x * z * (1 - c) + y * s, 0};
  r.m[1] = {x * y * (1 - c) + z * s, y * y + (1 - y * y) * c, y * z * (1 - c) - x * s, 0};
  r.m[2] = {x * z * (1 - c) - y * s, y * z * (1 - c) + x * s, z * z + (1 - z * z) * c, 0};
  return r;
}

std::optional<Mat4> Mat4::look_at(const Vec3& eye, const Vec3& look, const Vec3& up) {
  const double d[3] = {double(look.x) - eye.x, double(look.y) - eye.y, double(look.z) - eye.z};
  const double dl = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double ul = std::sqrt(double(up.x) * up.x + double(up.y) * up.y + double(up.z) * up.z);
  if (!(dl > 0) || !(ul > 0)) return std::nullopt;
  const double dir[3] = {d[0] / dl, d[1] / dl, d[2] / dl}, u[3] = {up.x / ul, up.y / ul, up.z / ul};
  // pbrt's left-handed camera frame: right = up x dir, new up = dir x right.
  double right[3] = {u[1] * dir[2] - u[2] * dir[1], u[2] * dir[0] - u[0] * dir[2], u[0] * dir[1] - u[1] * dir[0]};
  const double rl = std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
  if (!(rl > 1e-12)) return std::nullopt;
  for (double& r : right) r /= rl;
  const double nu[3] = {dir[1] * right[2] - dir[2] * right[1], dir[2] * right[0] - dir[0] * right[2],
                        dir[0] * right[1] - dir[1] * right[0]};
  Mat4 world_from_camera;
  for (int i = 0; i < 3; ++i) {
    world_from_camera.m[i][0] = right[i];
    world_from_camera.m[i][1] = nu[i];
    world_from_camera.m[i][2] = dir[i];
  }
  world_from_camera.m[0][3] = eye.x, world_from_camera.m[1][3] = eye.y, world_from_camera.m[2][3] = eye.z;
  return world_from_camera.inverse();
}

Mat4 Mat4::from_pbrt(const double* v) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = v[j * 4 + i];
  return r;
}

std::optional<Mat4> Mat4::inverse() const {
  // Gauss-Jordan elimination with partial pivoting.
  std::array<std::array<double, 8>, 4> a{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) a[i][j] = m[i][j], a[i][j + 4] = i == j;
  for (int c = 0; c < 4; ++c) {
    int p = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    if (!(std::abs(a[p][c]) > 1e-300)) return std::nullopt;
    std::swap(a[c], a[p]);
    const double inv = 1 / a[c][c];
    for (double& x : a[c]) x *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == c || a[r][c] == 0) continue;
      const double f = a[r][c];
      for (int k = 0; k < 8; ++k) a[r][k] -= f * a[c][k];
    }
  }
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = a[i][j + 4];
  for (const auto& row : r.m)
    for (double x : row)
      if (!std::isfinite(x)) return std::nullopt;
  return r;
}

double Mat4::det3() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Vec3 Mat4::point(const Vec3& p) const {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = float(m[i][0] * p.x + m[i][1] * p.y + m[i][2] * p.z + m[i][3]);
  return r;
}

Vec3 Mat4::vector(const Vec3& v) const {
  Vec3 r;
  for (int i = 0; i < 3; ++i) r[i] = float(m[i][0] * v.x + m[i][1] * v.y + m[i][2] * v.z);
  return r;
}

Affine Mat4::to_affine() const {
  Affine a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) a.m[i][j] = float(m[i][j]);
  return a;
}

MotionKey decompose(const Mat4& m, double* shear) {
  MotionKey k;
  k.translate = {float(m.m[0][3]), float(m.m[1][3]), float(m.m[2][3])};
  // Polar decomposition of the 3x3 part M = R S: R is the limit of R <- (R + R^-T) / 2. A
  // reflection (det < 0) is moved into S as a negative x scale first, so R is a rotation.
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m.m[i][j];
  const bool flip = m.det3() < 0;
  if (flip)
    for (int i = 0; i < 3; ++i) a[i][0] = -a[i][0];
  double r[3][3];
  std::copy(&a[0][0], &a[0][0] + 9, &r[0][0]);
  for (int it = 0; it < 100; ++it) {
    // inverse transpose of r
    const double c00 = r[1][1] * r[2][2] - r[1][2] * r[2][1], c01 = r[1][2] * r[2][0] - r[1][0] * r[2][2],
                 c02 = r[1][0] * r[2][1] - r[1][1] * r[2][0];
    const double c10 = r[0][2] * r[2][1] - r[0][1] * r[2][2], c11 = r[0][0] * r[2][2] - r[0][2] * r[2][0],
                 c12 = r[0][1] * r[2][0] - r[0][0] * r[2][1];
    const double c20 = r[0][1] * r[1][2] - r[0][2] * r[1][1], c21 = r[0][2] * r[1][0] - r[0][0] * r[1][2],
                 c22 = r[0][0] * r[1][1] - r[0][1] * r[1][0];
    const double det = r[0][0] * c00 + r[0][1] * c01 + r[0][2] * c02;
    if (!(std::abs(det) > 1e-300)) break;
    const double it_[3][3] = {
        {c00 / det, c01 / det, c02 / det}, {c10 / det, c11 / det, c12 / det}, {c20 / det, c21 / det, c22 / det}};
    double change = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double n = 0.5 * (r[i][j] + it_[i][j]);
        change = std::max(change, std::abs(n - r[i][j]));
        r[i][j] = n;
      }
    if (change < 1e-15) break;
  }
  // S = R^T M
  double s[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[i][j] = r[0][i] * a[0][j] + r[1][i] * a[1][j] + r[2][i] * a[2][j];
  double diag = std::max({std::abs(s[0][0]), std::abs(s[1][1]), std::abs(s[2][2])}), off = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) off = std::max(off, std::abs(s[i][j]));
  if (shear) *shear = diag > 0 ? off / diag : 0;
  k.scale = {float(flip ? -s[0][0] : s[0][0]), float(s[1][1]), float(s[2][2])};
  // Rotation matrix to quaternion (Shepperd's method: the largest of w, x, y, z first).
  const double tr = r[0][0] + r[1][1] + r[2][2];
  double w, x, y, z;
  if (tr > 0) {
    const double q = std::sqrt(tr + 1) * 2;
    w = 0.25 * q, x = (r[2][1] - r[1][2]) / q, y = (r[0][2] - r[2][0]) / q, z = (r[1][0] - r[0][1]) / q;
  } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
    const double q = std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]) * 2;
    w = (r[2][1] - r[1][2]) / q, x = 0.25 * q, y = (r[0][1] + r[1][0]) / q, z = (r[0][2] + r[2][0]) / q;
  } else if (r[1][1] > r[2][2]) {
    const double q = std::sqrt(1 + r[1][1] - r[0][0] - r[2][2]) * 2;
    w = (r[0][2] - r[2][0]) / q, x = (r[0][1] + r[1][0]) / q, y = 0.25 * q, z = (r[1][2] + r[2][1]) / q;
  } else {
    const double q = std::sqrt(1 + r[2][2] - r[0][0] - r[1][1]) * 2;
    w = (r[1][0] - r[0][1]) / q, x = (r[0][2] + r[2][0]) / q, y = (r[1][2] + r[2][1]) / q, z = 0.25 * q;
  }
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  k.rotate = {float(w / n), float(x / n), float(y / n), float(z / n)};
  return k;
}

}  // namespace pdrt
