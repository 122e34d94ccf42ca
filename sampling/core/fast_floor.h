#pragma once
// floor() as an int without a libm call, for the grid lookups of the samplers (x is a few
// cells around the unit cube, far inside int's range).

namespace pdrt {

inline int floor_int(double x) {
  const int i = int(x);
  return i - int(x < double(i));
}

}  // namespace pdrt
