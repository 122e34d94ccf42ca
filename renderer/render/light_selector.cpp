#include "renderer/render/light_selector.h"

#include <algorithm>

namespace pdrt {

LightSelector::LightSelector(const std::vector<LightBounds>& bounded, std::vector<InfiniteLightBounds> infinite)
    : bounded_(bounded.size()), bvh_(bounded), infinite_(std::move(infinite)) {}

bool LightSelector::select(const Vec3& p, const Vec3& n, float u, std::size_t* light, float* pmf) const {
  // The lights at infinity against the BVH's root, all as irradiance estimates: each takes
  // its share of [0, 1) in turn, the BVH the rest, with the pick number rescaled to it.
  // Without lights at infinity the root's importance is not needed (the BVH fails if all of
  // its lights have none). select_pmf() repeats exactly this arithmetic.
  const std::size_t ni = infinite_.size();
  float inf = 0;
  for (std::size_t k = 0; k < ni; ++k) inf += infinite_[k].importance(n);
  const float b = inf > 0 ? bvh_.importance(p, n) : 1.0f, total = inf + b;
  if (!(total > 0)) return false;
  float c = 0;  // the shares of the lights at infinity passed so far
  for (std::size_t k = 0; k < ni; ++k) {
    const float pk = infinite_[k].importance(n) / total;
    if (pk > 0 && u < c + pk) {
      *light = bounded_ + k, *pmf = pk;
      return true;
    }
    c += pk;
  }
  if (!(b > 0 && c < 1)) return false;
  u = std::min((u - c) / (1 - c), 0x1.fffffep-1f);
  int id;
  float pb;
  if (!bvh_.sample(p, n, u, &id, &pb)) return false;
  *light = std::size_t(id), *pmf = (1 - c) * pb;
  return *pmf > 0;
}

float LightSelector::select_pmf(const Vec3& p, const Vec3& n, std::size_t light) const {
  const std::size_t ni = infinite_.size();  // as in select()
  float inf = 0;
  for (std::size_t k = 0; k < ni; ++k) inf += infinite_[k].importance(n);
  const float b = inf > 0 ? bvh_.importance(p, n) : 1.0f, total = inf + b;
  if (!(total > 0)) return 0;
  if (light >= bounded_) {
    const std::size_t k = light - bounded_;
    return k < ni ? infinite_[k].importance(n) / total : 0.0f;
  }
  float c = 0;
  for (std::size_t k = 0; k < ni; ++k) c += infinite_[k].importance(n) / total;
  if (!(b > 0 && c < 1)) return 0;
  return (1 - c) * bvh_.pmf(p, n, int(light));
}

}  // namespace pdrt
