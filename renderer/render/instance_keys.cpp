#include "renderer/render/instance_keys.h"

#include <cmath>

namespace pdrt {

namespace {

struct D3 {
  double x = 0, y = 0, z = 0;
};
double dot3(const D3& a, const D3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 sub(const D3& a, const D3& b, double s) { return {a.x - b.x * s, a.y - b.y * s, a.z - b.z * s}; }
D3 scaled(const D3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
D3 cross3(const D3& a, const D3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The unit quaternion of rotation matrix columns (c0, c1, c2) (Shoemake 1985: the largest
// of w, x, y, z first, for accuracy).
Quat quat_of(const D3& c0, const D3& c1, const D3& c2) {
  const double m00 = c0.x, m10 = c0.y, m20 = c0.z, m01 = c1.x, m11 = c1.y, m21 = c1.z, m02 = c2.x, m12 = c2.y,
               m22 = c2.z;
  const double tr = m00 + m11 + m22;
  double w, x, y, z;
  if (tr > 0) {
    const double s = 2 * std::sqrt(tr + 1);
    w = s / 4, x = (m21 - m12) / s, y = (m02 - m20) / s, z = (m10 - m01) / s;
  } else if (m00 > m11 && m00 > m22) {
    const double s = 2 * std::sqrt(1 + m00 - m11 - m22);
    w = (m21 - m12) / s, x = s / 4, y = (m01 + m10) / s, z = (m02 + m20) / s;
  } else if (m11 > m22) {
    const double s = 2 * std::sqrt(1 + m11 - m00 - m22);
    w = (m02 - m20) / s, x = (m01 + m10) / s, y = s / 4, z = (m12 + m21) / s;
  } else {
    const double s = 2 * std::sqrt(1 + m22 - m00 - m11);
    w = (m10 - m01) / s, x = (m02 + m20) / s, y = (m12 + m21) / s, z = s / 4;
  }
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  return {float(w / n), float(x / n), float(y / n), float(z / n)};
}

}  // namespace

InstanceKey instance_key(const MotionKey& key, const Affine& static_part) {
  const Affine k = key.matrix();
  // L = (R S_key) A in double; columns l0, l1, l2.
  D3 l[3];
  for (int c = 0; c < 3; ++c) {
    double v[3];
    for (int r = 0; r < 3; ++r) {
      v[r] = 0;
      for (int i = 0; i < 3; ++i) v[r] += double(k.m[r][i]) * double(static_part.m[i][c]);
    }
    l[c] = {v[0], v[1], v[2]};
  }
  // Gram-Schmidt: L = Q U; q2 = q0 x q1 keeps Q a rotation (a mirror goes into U's last entry).
  const double u00 = std::sqrt(dot3(l[0], l[0]));
  const D3 q0 = scaled(l[0], 1 / u00);
  const double u01 = dot3(q0, l[1]);
  const D3 v1 = sub(l[1], q0, u01);
  const double u11 = std::sqrt(dot3(v1, v1));
  const D3 q1 = scaled(v1, 1 / u11);
  const D3 q2 = cross3(q0, q1);
  const double u02 = dot3(q0, l[2]), u12 = dot3(q1, l[2]), u22 = dot3(q2, l[2]);
  InstanceKey out;
  out.rotate = quat_of(q0, q1, q2);
  out.scale[0] = float(u00), out.scale[1] = float(u11), out.scale[2] = float(u22);
  out.skew[0] = float(u01), out.skew[1] = float(u02), out.skew[2] = float(u12);
  // world = T_key + L p + (R S_key) b = T_key + Q U (p + A^-1 b): the shift is U A^-1 b.
  // A^-1 b is minus the inverse's translation.
  const Affine inv = static_part.inverse();
  const D3 c{-double(inv.m[0][3]), -double(inv.m[1][3]), -double(inv.m[2][3])};
  out.shift[0] = float(u00 * c.x + u01 * c.y + u02 * c.z);
  out.shift[1] = float(u11 * c.y + u12 * c.z);
  out.shift[2] = float(u22 * c.z);
  out.translate = key.translate;
  return out;
}

bool embree_follows_keys(const std::vector<MotionKey>& keys, const Affine& static_part) {
  const auto& a = static_part.m;
  const bool upper = a[1][0] == 0 && a[2][0] == 0 && a[2][1] == 0;
  bool uniform = true;
  for (const MotionKey& k : keys) uniform = uniform && k.scale.x == k.scale.y && k.scale.y == k.scale.z;
  if (!upper && !uniform) return false;
  for (size_t i = 1; i < keys.size(); ++i)
    for (int c = 0; c < 3; ++c)
      if ((keys[i].scale[c] < 0) != (keys[0].scale[c] < 0)) return false;
  return true;
}

}  // namespace pdrt
