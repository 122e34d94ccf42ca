#include "sampling/measures/kd_tree.h"

#include "sampling/core/distance.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pdrt {
namespace {
constexpr uint32_t kLeafSize = 8;
}

KdTree::KdTree(std::span<const double> coords, int dim, bool periodic) : dim_(dim), periodic_(periodic) {
  const std::size_t n = dim > 0 ? coords.size() / std::size_t(dim) : 0;
  ids_.resize(n);
  std::iota(ids_.begin(), ids_.end(), 0u);
  // Build on the input coordinates (ids_ is permuted in place), then copy in tree order.
  pts_.assign(coords.begin(), coords.begin() + std::ptrdiff_t(n * dim));
  nodes_.reserve(4 * (n / kLeafSize + 1));
  lo_.reserve(nodes_.capacity() * dim);
  hi_.reserve(nodes_.capacity() * dim);
  if (n > 0) build(0, uint32_t(n));
  std::vector<double> ordered(n * dim);
  for (std::size_t s = 0; s < n; ++s) std::copy_n(&pts_[std::size_t(ids_[s]) * dim], dim, &ordered[s * dim]);
  pts_.swap(ordered);
}

int32_t KdTree::build(uint32_t begin, uint32_t end) {
  int32_t index = int32_t(nodes_.size());
  nodes_.push_back({begin, end, -1, -1, kNone});
  lo_.resize(nodes_.size() * dim_);
  hi_.resize(nodes_.size() * dim_);
  double* lo = &lo_[std::size_t(index) * dim_];
  double* hi = &hi_[std::size_t(index) * dim_];
  std::fill_n(lo, dim_, std::numeric_limits<double>::infinity());
  std::fill_n(hi, dim_, -std::numeric_limits<double>::infinity());
  uint32_t min_id = kNone;
  for (uint32_t s = begin; s < end; ++s) {
    const double* p = &pts_[std::size_t(ids_[s]) * dim_];
    for (int k = 0; k < dim_; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    min_id = std::min(min_id, ids_[s]);
  }
  nodes_[index].min_id = min_id;
  if (end - begin <= kLeafSize) return index;
  int axis = 0;
  for (int k = 1; k < dim_; ++k)
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(ids_.begin() + begin, ids_.begin() + mid, ids_.begin() + end, [&](uint32_t a, uint32_t b) {
    return pts_[std::size_t(a) * dim_ + axis] < pts_[std::size_t(b) * dim_ + axis];
  });
  int32_t left = build(begin, mid);
  int32_t right = build(mid, end);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

double KdTree::box_dist_sq(int32_t node, const double* q) const {
  const double* lo = &lo_[std::size_t(node) * dim_];
  const double* hi = &hi_[std::size_t(node) * dim_];
  double s = 0.0;
  for (int k = 0; k < dim_; ++k) {
    double d = 0.0;
    if (q[k] < lo[k] || q[k] > hi[k]) {
      if (periodic_) {
        // On the circle the nearest point of an interval not holding q is an endpoint.
        d = std::min(std::abs(axis_delta(q[k], lo[k], true)), std::abs(axis_delta(q[k], hi[k], true)));
      } else {
        d = q[k] < lo[k] ? lo[k] - q[k] : q[k] - hi[k];
      }
    }
    s += d * d;
  }
  return s;
}

void KdTree::nearest_rec(int32_t node, const double* q, uint32_t exclude, uint32_t before, Hit& best) const {
  const Node& nd = nodes_[node];
  if (nd.min_id >= before) return;
  if (nd.left < 0) {
    for (uint32_t s = nd.begin; s < nd.end; ++s) {
      uint32_t id = ids_[s];
      if (id == exclude || id >= before) continue;
      double d2 = distance_sq(q, &pts_[std::size_t(s) * dim_], dim_, periodic_);
      if (d2 < best.dist_sq) best = {id, d2};
    }
    return;
  }
  double dl = box_dist_sq(nd.left, q), dr = box_dist_sq(nd.right, q);
  int32_t first = nd.left, second = nd.right;
  if (dr < dl) std::swap(first, second), std::swap(dl, dr);
  if (dl < best.dist_sq) nearest_rec(first, q, exclude, before, best);
  if (dr < best.dist_sq) nearest_rec(second, q, exclude, before, best);
}

KdTree::Hit KdTree::nearest(const double* q, double limit_sq, uint32_t exclude, uint32_t before) const {
  Hit best;
  best.dist_sq = limit_sq;
  if (nodes_.empty() || box_dist_sq(0, q) >= limit_sq) return best;
  nearest_rec(0, q, exclude, before, best);
  return best;
}

void KdTree::within_rec(int32_t node, const double* q, double radius_sq, std::vector<Hit>& out) const {
  const Node& nd = nodes_[node];
  if (nd.left < 0) {
    for (uint32_t s = nd.begin; s < nd.end; ++s) {
      double d2 = distance_sq(q, &pts_[std::size_t(s) * dim_], dim_, periodic_);
      if (d2 <= radius_sq) out.push_back({ids_[s], d2});
    }
    return;
  }
  if (box_dist_sq(nd.left, q) <= radius_sq) within_rec(nd.left, q, radius_sq, out);
  if (box_dist_sq(nd.right, q) <= radius_sq) within_rec(nd.right, q, radius_sq, out);
}

void KdTree::within(const double* q, double radius_sq, std::vector<Hit>& out) const {
  if (nodes_.empty() || box_dist_sq(0, q) > radius_sq) return;
  within_rec(0, q, radius_sq, out);
}

}  // namespace pdrt
