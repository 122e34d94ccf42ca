// progressive_order (progressive_order.h).
#include "sampling/samplers/progressive_order.h"

#include <bit>

namespace pdrt {

std::optional<std::vector<uint32_t>> progressive_order(const uint32_t* coords, uint32_t n, int dim, std::string* why) {
  if (n == 0 || (n & (n - 1)) != 0) {
    *why = std::to_string(n) + " points per table, not a power of two";
    return std::nullopt;
  }
  std::vector<uint32_t> order(n), at(n);  // at[stratum of the current width] = progressive index there
  order[0] = 0;
  for (uint32_t level = 1; level < n; level *= 2) {  // indices [level, 2 level) fill the other halves
    const int w = std::countr_zero(level);           // strata of width 2^-w hold one earlier point each
    for (uint32_t j = 0; j < level; ++j) at[w ? coords[std::size_t(order[j]) * dim] >> (32 - w) : 0] = j;
    std::vector<bool> taken(level, false);
    for (uint32_t i = level; i < 2 * level; ++i) {
      const uint32_t x = coords[std::size_t(i) * dim];
      const uint32_t partner = at[w ? x >> (32 - w) : 0];
      if (taken[partner]) {
        *why = "its first " + std::to_string(2 * level) + " points are not stratified along the first axis";
        return std::nullopt;
      }
      taken[partner] = true;
      order[level + partner] = i;
    }
    // The partner's half of its stratum must be the other one.
    for (uint32_t j = 0; j < level; ++j)
      if (((coords[std::size_t(order[j]) * dim] ^ coords[std::size_t(order[level + j]) * dim]) >> (31 - w)) != 1u) {
        *why = "its first " + std::to_string(2 * level) + " points are not stratified along the first axis";
        return std::nullopt;
      }
  }
  return order;
}

}  // namespace pdrt
