#include "renderer/scene/transform.h"

#include <cmath>

namespace pdrt {

Affine Affine::translate(const Vec3& t) {
  Affine a;
  a.m[0][3] = t.x, a.m[1][3] = t.y, a.m[2][3] = t.z;
  return a;
}

Affine Affine::scale(const Vec3& s) {
  Affine a;
  a.m[0][0] = s.x, a.m[1][1] = s.y, a.m[2][2] = s.z;
  return a;
}

Affine Affine::rotate(const Vec3& axis, float degrees) {
  Vec3 u = normalize(axis);
  float r = degrees * kPi / 180.0f, c = std::cos(r), s = std::sin(r), k = 1 - c;
  Affine a;
  a.m[0] = {c + u.x * u.x * k, u.x * u.y * k - u.z * s, u.x * u.z * k + u.y * s, 0};
  a.m[1] = {u.y * u.x * k + u.z * s, c + u.y * u.y * k, u.y * u.z * k - u.x * s, 0};
  a.m[2] = {u.z * u.x * k - u.y * s, u.z * u.y * k + u.x * s, c + u.z * u.z * k, 0};
  return a;
}

Vec3 Affine::point(const Vec3& p) const {
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
          m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
}

Vec3 Affine::vector(const Vec3& v) const {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

float Affine::determinant() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Affine Affine::inverse() const {
  float d = 1.0f / determinant();
  Affine r;
  r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * d;
  r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * d;
  r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * d;
  r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * d;
  r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * d;
  r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * d;
  r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * d;
  r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * d;
  r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * d;
  Vec3 t = r.vector({m[0][3], m[1][3], m[2][3]});
  r.m[0][3] = -t.x, r.m[1][3] = -t.y, r.m[2][3] = -t.z;
  return r;
}

Vec3 Affine::transpose_vector(const Vec3& v) const {
  return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
          m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
}

Vec3 Affine::normal(const Vec3& n) const { return inverse().transpose_vector(n); }  // n' = (M^-1)^T n

Affine operator*(const Affine& a, const Affine& b) {
  Affine r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      float s = j == 3 ? a.m[i][3] : 0.0f;
      for (int k = 0; k < 3; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

Quat Quat::from_axis_angle(const Vec3& axis, float degrees) {
  Vec3 u = normalize(axis);
  float h = 0.5f * degrees * kPi / 180.0f, s = std::sin(h);
  return {std::cos(h), u.x * s, u.y * s, u.z * s};
}

Quat slerp(float t, Quat a, const Quat& b) {
  float d = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  if (d < 0) a = {-a.w, -a.x, -a.y, -a.z}, d = -d;  // shortest arc
  float wa, wb;
  if (d > 0.9995f) {
    wa = 1 - t, wb = t;
  } else {
    float th = std::acos(d), s = std::sin(th);
    wa = std::sin((1 - t) * th) / s, wb = std::sin(t * th) / s;
  }
  Quat q{wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z};
  float n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Affine MotionKey::matrix() const {
  const Quat& q = rotate;
  Affine r;
  r.m[0] = {1 - 2 * (q.y * q.y + q.z * q.z), 2 * (q.x * q.y - q.w * q.z), 2 * (q.x * q.z + q.w * q.y), 0};
  r.m[1] = {2 * (q.x * q.y + q.w * q.z), 1 - 2 * (q.x * q.x + q.z * q.z), 2 * (q.y * q.z - q.w * q.x), 0};
  r.m[2] = {2 * (q.x * q.z - q.w * q.y), 2 * (q.y * q.z + q.w * q.x), 1 - 2 * (q.x * q.x + q.y * q.y), 0};
  return Affine::translate(translate) * r * Affine::scale(scale);
}

MotionKey interpolate(const MotionKey* keys, int count, float time) {
  if (count <= 0) return {};
  if (time <= keys[0].time || count == 1) return keys[0];
  if (time >= keys[count - 1].time) return keys[count - 1];
  int i = 0;
  while (i + 2 < count && keys[i + 1].time <= time) ++i;
  const MotionKey &a = keys[i], &b = keys[i + 1];
  float t = (time - a.time) / (b.time - a.time);
  MotionKey k;
  k.time = time;
  k.translate = lerp(t, a.translate, b.translate);
  k.rotate = slerp(t, a.rotate, b.rotate);
  k.scale = lerp(t, a.scale, b.scale);
  return k;
}

}  // namespace pdrt
