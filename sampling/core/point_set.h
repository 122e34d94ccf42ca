#pragma once
// A set of points in [0,1)^dim, stored interleaved, in generation order.
#include <cstddef>
#include <span>
#include <vector>

namespace pdrt {

// The most coordinates a point has (generators, point CSV files).
inline constexpr int kMaxDim = 8;

struct PointSet {
  int dim = 2;
  bool periodic = false;
  std::vector<double> coords;  // size() * dim values, point i at [i*dim, (i+1)*dim)
  // Per point: the minimum-distance radius in force when it was placed (pdrt's
  // "radius" = minimum distance between points). Empty when the method has none.
  std::vector<double> radius;

  std::size_t size() const { return dim > 0 ? coords.size() / std::size_t(dim) : 0; }
  std::span<const double> point(std::size_t i) const { return {coords.data() + i * dim, std::size_t(dim)}; }
  std::span<double> point(std::size_t i) { return {coords.data() + i * dim, std::size_t(dim)}; }
  bool has_radius() const { return !radius.empty(); }
};

}  // namespace pdrt
