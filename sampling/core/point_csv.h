#pragma once
// The point-set CSV format of `pdrt sample`: header x0,x1,...[,radius], one point per
// row in generation order, each value in the shortest form that reads back exactly.
#include "sampling/core/point_set.h"

#include <filesystem>

namespace pdrt {

void write_point_csv(const std::filesystem::path& path, const PointSet& points);

// Reads and validates a point CSV. Throws InputError naming file:line for an empty file,
// a bad header, a wrong column count, non-numeric/NaN values or coordinates outside [0,1).
PointSet read_point_csv(const std::filesystem::path& path);

}  // namespace pdrt
