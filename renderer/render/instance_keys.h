#pragma once
// An instance's transform at one time step as Embree's quaternion decomposition
// (rtcSetGeometryTransformQuaternion: world = T * R * S, S upper triangular with a shift),
// for world(t) = interpolate(motion, t) * static_part. Embree slerps R and interpolates T and S
// linearly between steps; that equals pdrt's keyframe interpolation (transform.h) exactly when
// the steps' S vary linearly and R by a constant right factor, which embree_follows_keys() tells.
#include "renderer/scene/transform.h"

#include <vector>

namespace pdrt {

struct InstanceKey {
  Vec3 translate{0.0f};
  Quat rotate{};
  float scale[3] = {1, 1, 1};
  float skew[3] = {0, 0, 0};   // xy, xz, yz: S's entries above the diagonal
  float shift[3] = {0, 0, 0};  // S's last column
};

// key.matrix() * static_part decomposed: its 3x3 part L = Q U (Gram-Schmidt, Q a rotation,
// U upper triangular) and its translation split into the key's own T and a pivot shift
// U A^-1 b in the prototype's space, so the static translation turns with the rotation.
InstanceKey instance_key(const MotionKey& key, const Affine& static_part);

// True when Embree's interpolation of instance_key() between consecutive keys is pdrt's:
// the static part's 3x3 is upper triangular (no rotation to commute with a non-uniform scale)
// or every key scales uniformly, and no scale changes sign between keys.
bool embree_follows_keys(const std::vector<MotionKey>& keys, const Affine& static_part);

}  // namespace pdrt
