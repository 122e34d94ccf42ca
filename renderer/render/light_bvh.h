#pragma once
// A bounding-volume hierarchy over emitters' LightBounds for choosing one emitter in
// proportion to its estimated contribution at a shading point (pbrt-v4 §12.6.3
// BVHLightSampler; Conty Estevez and Kulla, HPG 2018). Sampling descends from the root,
// choosing a child with probability proportional to its importance and rescaling the pick
// number; pmf() retraces the same choices from a per-light bit trail, so it is exactly the
// probability sample() gave (multiple importance sampling needs the same value).
#include "renderer/render/light_bounds.h"

#include <cstdint>
#include <vector>

namespace pdrt {

class LightBvh {
 public:
  LightBvh() = default;
  explicit LightBvh(const std::vector<LightBounds>& lights);  // light ids are the indices
  bool empty() const { return nodes_.empty(); }

  // Importance of all lights together at p with unit normal n.
  float importance(const Vec3& p, const Vec3& n) const { return empty() ? 0.0f : nodes_[0].bounds.importance(p, n); }
  // Chooses a light with u in [0, 1); false when every light's importance at p is zero.
  bool sample(const Vec3& p, const Vec3& n, float u, int* light, float* pmf) const;
  // The probability that sample() chooses `light` at p (given that it is called).
  float pmf(const Vec3& p, const Vec3& n, int light) const;

 private:
  struct Node {
    PackedLightBounds bounds;
    int second = -1;      // interior: index of the second child (the first follows the node)
    int light = -1;       // leaf: the light id
    bool halves = false;  // interior: the children's bounds agree (the two triangles of a quad), so
                          // each gets 1/2 without evaluating them; any fixed split is unbiased
  };
  // Builds the subtree of ids[begin, end) and returns its bounds.
  LightBounds build(std::vector<int>& ids, std::vector<Vec3>& centroids, const std::vector<LightBounds>& lights,
                    int begin, int end, int depth, uint64_t trail);
  // Probability of taking the first child of interior node `i` at p; false if neither child
  // has importance.
  bool first_child_probability(int i, const Vec3& p, const Vec3& n, float* p0) const;

  std::vector<Node> nodes_;
  std::vector<uint64_t> trail_;  // per light: bit k set = the second child at depth k
};

}  // namespace pdrt
