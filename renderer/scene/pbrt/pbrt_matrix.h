#pragma once
// 4x4 double matrices for the pbrt importer: pbrt-v4's transform directives (Translate, Scale,
// Rotate, LookAt, Transform, ConcatTransform) compose projective 4x4 matrices; pdrt's scene
// holds affine ones (transform.h), so the importer works in doubles and converts at the end.
#include "renderer/scene/transform.h"

#include <array>
#include <optional>

namespace pdrt {

struct Mat4 {
  std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

  static Mat4 translate(double x, double y, double z);
  static Mat4 scale(double x, double y, double z);
  static Mat4 rotate(double degrees, double x, double y, double z);  // about a non-zero axis, right-handed
  // pbrt-v4's LookAt: the camera-from-world matrix of a camera at `eye` looking at `look` with
  // `up`; nullopt when look == eye or up is parallel to the view direction.
  static std::optional<Mat4> look_at(const Vec3& eye, const Vec3& look, const Vec3& up);
  // The matrix of `Transform`/`ConcatTransform`: pbrt files list it column by column.
  static Mat4 from_pbrt(const double* v16);

  std::optional<Mat4> inverse() const;  // nullopt when singular
  bool affine() const { return m[3][0] == 0 && m[3][1] == 0 && m[3][2] == 0 && m[3][3] == 1; }
  double det3() const;              // of the upper-left 3x3: < 0 swaps handedness
  Vec3 point(const Vec3& p) const;  // affine part only
  Vec3 vector(const Vec3& v) const;
  Affine to_affine() const;  // the upper 3x4, in float
  bool operator==(const Mat4& o) const { return m == o.m; }
};
Mat4 operator*(const Mat4& a, const Mat4& b);

// An affine matrix as pdrt's keyframe, T * R * S, by polar decomposition (pbrt-v4's
// AnimatedTransform does the same). `shear` returns the largest off-diagonal element of the
// stretch, relative to its largest diagonal one: pdrt's keys hold no shear, so it is dropped.
MotionKey decompose(const Mat4& m, double* shear);

}  // namespace pdrt
