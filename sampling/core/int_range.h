#pragma once
// A closed range of non-negative integers: the one definition of what a count, size or seed
// may be, shared by the command line and the files that set the same value.
#include <cstdint>
#include <string>

namespace pdrt {

struct IntRange {
  uint64_t lo, hi;
  bool contains(uint64_t v) const { return v >= lo && v <= hi; }
  std::string str() const {
    std::string s = "[";  // appended, not literal + string: GCC 12's -Wrestrict false positive
    s += std::to_string(lo);
    s += ", ";
    s += std::to_string(hi);
    s += "]";
    return s;
  }
};

}  // namespace pdrt
