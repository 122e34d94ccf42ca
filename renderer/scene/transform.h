#pragma once
// Affine transforms (3x4, column vectors) and the decomposed keyframes motion blur
// interpolates: scale, then rotation (unit quaternion, slerped), then translation.
#include "renderer/scene/vec3.h"

#include <array>

namespace pdrt {

struct Affine {
  // Row-major 3x4: p' = M[0..2][0..2] p + M[.][3].
  std::array<std::array<float, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  static Affine translate(const Vec3& t);
  static Affine scale(const Vec3& s);
  static Affine rotate(const Vec3& axis, float degrees);  // axis need not be unit, must be non-zero
  Vec3 point(const Vec3& p) const;
  Vec3 vector(const Vec3& v) const;
  Vec3 normal(const Vec3& n) const;            // by the inverse transpose; not normalised
  Vec3 transpose_vector(const Vec3& v) const;  // M^T v (of the 3x3 part): inverse().transpose_vector is normal()
  Affine inverse() const;
  float determinant() const;
};
Affine operator*(const Affine& a, const Affine& b);

struct Quat {
  float w = 1, x = 0, y = 0, z = 0;
  static Quat from_axis_angle(const Vec3& axis, float degrees);
};
Quat slerp(float t, Quat a, const Quat& b);

// One keyframe of an object's (or camera's) motion within the shutter interval.
struct MotionKey {
  float time = 0;
  Vec3 translate{0.0f};
  Quat rotate{};
  Vec3 scale{1.0f};
  Affine matrix() const;  // T * R * S
};

// The transform at `time`, interpolating between keyframes (sorted by time; clamped at the ends).
MotionKey interpolate(const MotionKey* keys, int count, float time);

}  // namespace pdrt
