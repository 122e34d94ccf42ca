#pragma once
// The order in which a progressive table's aligned blocks are stratified. The `poisson` tables
// keep every power-of-two prefix stratified but put each level [2^(L-1), 2^L) in farthest-point
// order (owen_poisson_2d.h), which keeps the prefixes and loses the aligned blocks inside a
// level. Screen-space sampling hands aligned blocks to neighbouring pixels, so it reads the
// tables in their progressive (Sobol-like) order: index j of level L is the point that shares
// the 2^-(L-1) stratum of axis 0 with index j - 2^(L-1). Then the point of index j lies in the
// 2^-s stratum of index j mod 2^s for every s, so every aligned block [a 2^s, (a + 1) 2^s)
// covers the strata of the 2^s prefix once: stratified on axis 0, and for an Owen-scrambled
// (0,2) sequence (the owen-pd tables) a (0,s,2)-net.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pdrt {

// order[j] = the table index of progressive index j, for a table of n points (a power of two)
// with `dim` 32-bit fixed-point values per point whose every power-of-two prefix has one point
// per 2^-L stratum of axis 0. Returns nullopt and says why in *why when the table is not such.
std::optional<std::vector<uint32_t>> progressive_order(const uint32_t* coords, uint32_t n, int dim, std::string* why);

}  // namespace pdrt
