#pragma once
// Static k-d tree over points in [0,1)^dim for nearest-neighbour and fixed-radius queries,
// Euclidean or toroidal. Each node keeps the tight bounding box of its points and the
// smallest point index below it, so a query can be limited to the points placed before
// index i (the nearest *earlier* neighbour used for prefix statistics).
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace pdrt {

class KdTree {
 public:
  static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

  struct Hit {
    uint32_t id = kNone;  // index into the input order; kNone when nothing qualified
    double dist_sq = std::numeric_limits<double>::infinity();
  };

  // `coords` holds n*dim values (point i at [i*dim, (i+1)*dim)); they are copied.
  KdTree(std::span<const double> coords, int dim, bool periodic);

  int dim() const { return dim_; }
  bool periodic() const { return periodic_; }
  std::size_t size() const { return ids_.size(); }

  // Nearest point strictly closer than sqrt(limit_sq), skipping index `exclude` and every
  // index >= `before`. Returns a Hit with id kNone when there is none.
  Hit nearest(const double* q, double limit_sq = std::numeric_limits<double>::infinity(), uint32_t exclude = kNone,
              uint32_t before = kNone) const;

  // Appends every point with squared distance <= radius_sq (id and distance) to `out`.
  void within(const double* q, double radius_sq, std::vector<Hit>& out) const;

 private:
  struct Node {
    uint32_t begin, end;  // range in the permuted arrays
    int32_t left, right;  // children, -1 for a leaf
    uint32_t min_id;      // smallest input index in the subtree
  };

  int32_t build(uint32_t begin, uint32_t end);
  double box_dist_sq(int32_t node, const double* q) const;
  void nearest_rec(int32_t node, const double* q, uint32_t exclude, uint32_t before, Hit& best) const;
  void within_rec(int32_t node, const double* q, double radius_sq, std::vector<Hit>& out) const;

  int dim_;
  bool periodic_;
  std::vector<double> pts_;    // coordinates in tree order
  std::vector<uint32_t> ids_;  // input index of each tree-order point
  std::vector<Node> nodes_;
  std::vector<double> lo_, hi_;  // per-node bounding boxes, dim_ values each
};

}  // namespace pdrt
