#pragma once
// Which light next-event estimation aims at, chosen by its estimated contribution at the
// shading point p with unit shading normal n (pbrt-v4's BVHLightSampler, lightsamplers.h;
// Conty Estevez and Kulla, HPG 2018): the bounded lights by the light BVH (light_bvh.h), the
// lights at infinity (distant lights, the environment) beside it on the same footing, all as
// irradiance estimates. Knows the lights only by their bounds.
#include "renderer/render/light_bounds.h"
#include "renderer/render/light_bvh.h"

#include <cstddef>
#include <vector>

namespace pdrt {

class LightSelector {
 public:
  LightSelector() = default;
  // Light ids: 0 .. bounded.size() - 1 in the BVH, then the lights at infinity in order.
  LightSelector(const std::vector<LightBounds>& bounded, std::vector<InfiniteLightBounds> infinite);
  std::size_t size() const { return bounded_ + infinite_.size(); }

  // A light for the pick number u in [0, 1) and the probability it was chosen; false when no
  // light can contribute at (p, n).
  bool select(const Vec3& p, const Vec3& n, float u, std::size_t* light, float* pmf) const;
  // The probability select() chooses `light` at (p, n): exactly the pmf it returns, for MIS.
  float select_pmf(const Vec3& p, const Vec3& n, std::size_t light) const;

 private:
  std::size_t bounded_ = 0;
  LightBvh bvh_;
  std::vector<InfiniteLightBounds> infinite_;
};

}  // namespace pdrt
