#include "renderer/render/light_bvh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pdrt {

namespace {

constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
constexpr int kBuckets = 12;
constexpr int kMaxDepth = 64;         // the bit trail's width
constexpr int kMedianFromDepth = 40;  // below this depth split by count, so the tree stays within kMaxDepth

// Orientation measure M_Omega of a normal cone widened by the emission angle (Conty Estevez
// and Kulla 2018, eq. 1): the solid angle, cosine-weighted past theta_o, that the group can
// emit into.
float orientation_measure(const LightBounds& b) {
  const float to = std::acos(std::clamp(b.normals.cos_theta, -1.0f, 1.0f));
  const float te = std::acos(std::clamp(b.cos_e, -1.0f, 1.0f));
  const float tw = std::min(to + te, kPi), sin_o = std::sin(to);
  return 2 * kPi * (1 - b.normals.cos_theta) +
         kPi / 2 * (2 * tw * sin_o - std::cos(to - 2 * tw) - 2 * to * sin_o + b.normals.cos_theta);
}

// Surface-area-orientation heuristic cost of a group (pbrt-v4's EvaluateCost): power x
// orientation measure x box area, with Kr penalising thin slabs split across their width.
float split_cost(const LightBounds& b, const Box3& node_box, int axis) {
  const Vec3 d = node_box.diagonal();
  const float extent = d[axis], kr = extent > 0 ? max_component(d) / extent : 1.0f;
  return b.phi * orientation_measure(b) * kr * b.box.surface_area();
}

// Same box, normal cone, emission angle and sidedness, and power within 1e-5.
bool nearly_equal(const LightBounds& a, const LightBounds& b) {
  auto same = [](const Vec3& x, const Vec3& y, float tol) {
    return std::abs(x.x - y.x) <= tol && std::abs(x.y - y.y) <= tol && std::abs(x.z - y.z) <= tol;
  };
  const float size = max_component(a.box.diagonal()) + 1e-30f;
  return a.two_sided == b.two_sided && a.cos_e == b.cos_e && a.normals.cos_theta == b.normals.cos_theta &&
         same(a.normals.w, b.normals.w, 1e-6f) && same(a.box.lo, b.box.lo, 1e-6f * size) &&
         same(a.box.hi, b.box.hi, 1e-6f * size) && std::abs(a.phi - b.phi) <= 1e-5f * std::max(a.phi, b.phi);
}

}  // namespace

LightBvh::LightBvh(const std::vector<LightBounds>& lights) {
  if (lights.empty()) return;
  std::vector<int> ids(lights.size());
  std::vector<Vec3> centroids(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) ids[i] = int(i), centroids[i] = lights[i].box.center();
  trail_.assign(lights.size(), 0);
  nodes_.reserve(2 * lights.size());
  build(ids, centroids, lights, 0, int(ids.size()), 0, 0);
}

LightBounds LightBvh::build(std::vector<int>& ids, std::vector<Vec3>& centroids, const std::vector<LightBounds>& lights,
                            int begin, int end, int depth, uint64_t trail) {
  const int index = int(nodes_.size());
  nodes_.push_back({});
  if (end - begin == 1) {
    const int id = ids[begin];
    nodes_[index].bounds = PackedLightBounds(lights[id]);
    nodes_[index].light = id;
    trail_[id] = trail;
    return lights[id];
  }
  if (depth >= kMaxDepth) throw std::logic_error("light BVH deeper than its bit trail");
  LightBounds all;
  Box3 cbox;
  for (int i = begin; i < end; ++i) all = merge(all, lights[ids[i]]), cbox.extend(centroids[ids[i]]);

  // Best bucket boundary over the three axes (pbrt-v4 BVHLightSampler::buildBVH).
  int best_axis = -1, best_bucket = -1;
  float best_cost = INFINITY;
  if (depth < kMedianFromDepth) {
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = cbox.lo[axis], ext = cbox.hi[axis] - lo;
      if (!(ext > 0)) continue;
      LightBounds bucket[kBuckets];
      auto bucket_of = [&](int id) {
        return std::min(kBuckets - 1, int(kBuckets * ((centroids[id][axis] - lo) / ext)));
      };
      for (int i = begin; i < end; ++i) bucket[bucket_of(ids[i])] = merge(bucket[bucket_of(ids[i])], lights[ids[i]]);
      for (int split = 0; split < kBuckets - 1; ++split) {
        LightBounds below, above;
        for (int k = 0; k <= split; ++k) below = merge(below, bucket[k]);
        for (int k = split + 1; k < kBuckets; ++k) above = merge(above, bucket[k]);
        if (below.phi == 0 || above.phi == 0) continue;
        const float cost = split_cost(below, all.box, axis) + split_cost(above, all.box, axis);
        if (cost < best_cost) best_cost = cost, best_axis = axis, best_bucket = split;
      }
    }
  }
  int mid;
  if (best_axis >= 0) {
    const float lo = cbox.lo[best_axis], ext = cbox.hi[best_axis] - lo;
    auto* m = std::partition(ids.data() + begin, ids.data() + end, [&](int id) {
      return std::min(kBuckets - 1, int(kBuckets * ((centroids[id][best_axis] - lo) / ext))) <= best_bucket;
    });
    mid = int(m - ids.data());
  } else {
    // Coincident centroids (or deep in the tree): halve by count along the widest axis.
    const int axis = cbox.max_axis();
    mid = (begin + end) / 2;
    std::nth_element(ids.begin() + begin, ids.begin() + mid, ids.begin() + end, [&](int a, int b) {
      return centroids[a][axis] < centroids[b][axis] || (centroids[a][axis] == centroids[b][axis] && a < b);
    });
  }
  if (mid == begin || mid == end) mid = (begin + end) / 2;
  const LightBounds a = build(ids, centroids, lights, begin, mid, depth + 1, trail);
  nodes_[index].second = int(nodes_.size());
  const LightBounds b = build(ids, centroids, lights, mid, end, depth + 1, trail | (uint64_t(1) << depth));
  nodes_[index].bounds = PackedLightBounds(all);
  nodes_[index].halves = nearly_equal(a, b);
  return all;
}

bool LightBvh::first_child_probability(int i, const Vec3& p, const Vec3& n, float* p0) const {
  if (nodes_[i].halves) {
    *p0 = 0.5f;
    return true;
  }
  const float i0 = nodes_[i + 1].bounds.importance(p, n), i1 = nodes_[nodes_[i].second].bounds.importance(p, n);
  if (!(i0 + i1 > 0)) return false;
  *p0 = i0 / (i0 + i1);
  return true;
}

bool LightBvh::sample(const Vec3& p, const Vec3& n, float u, int* light, float* pmf) const {
  if (empty()) return false;
  float prob = 1;
  int i = 0;
  while (nodes_[i].light < 0) {
    float p0;
    if (!first_child_probability(i, p, n, &p0)) return false;
    if (u < p0) {
      u = std::min(u / p0, kOneMinusEpsilon);
      prob *= p0;
      i = i + 1;
    } else {
      u = std::min((u - p0) / (1 - p0), kOneMinusEpsilon);
      prob *= 1 - p0;
      i = nodes_[i].second;
    }
  }
  *light = nodes_[i].light;
  *pmf = prob;
  return prob > 0;
}

float LightBvh::pmf(const Vec3& p, const Vec3& n, int light) const {
  if (empty()) return 0;
  const uint64_t trail = trail_[light];
  float prob = 1;
  int i = 0;
  for (int k = 0; nodes_[i].light < 0; ++k) {
    float p0;
    if (!first_child_probability(i, p, n, &p0)) return 0;
    if ((trail >> k) & 1) {
      prob *= 1 - p0;
      i = nodes_[i].second;
    } else {
      prob *= p0;
      i = i + 1;
    }
  }
  return prob;
}

}  // namespace pdrt
