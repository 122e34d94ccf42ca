#pragma once
// `poisson-ss`: `poisson`'s tables arranged in screen space (issue 31 item 1; Cook 1986 §5's
// prototype patterns "in screen space", in the hierarchical form of Ahmed & Wonka 2020).
// Per (family, bounce, seed) every pixel's samples take one aligned block of a global index:
// the pixel's Morton index followed by the sample's, with its base-4 digits permuted, each by
// one of the 24 permutations picked by a hash of the digits above it (Ahmed & Wonka §4; the
// same nesting as `zsobol`; the sample's digits four nodes to a hash), so aligned blocks of
// indices stay aligned blocks. Each run of M
// consecutive indices (M = a table's points: 1024 for the 2-D families, 2048 for time) is one
// table read in its progressive order (progressive_order.h), picked by a hash of the run from
// the family's first 8 (a cache-sized pool), with one digital shift (and an axis swap) for the
// run. Aligned blocks of the owen-pd tables are
// (0,m,2)-nets, so a pixel's 2^m samples, those of every 2 x 2, 4 x 4, ... group of pixels
// around it that fits in one run, are nets and spread over the plane of samples: the error of
// neighbouring pixels is complementary (blue noise on screen).
//
// Unbiased over seeds: every run's digital shift is uniform and independent of the others',
// so every value is uniform on the 2^-32 grid and the families and bounces are independent.
// Adaptive refinement: the samples of a pixel past its block (index >= 2^m) take block
// b = index >> m in a fresh arrangement (the key hashed with b), so every block of every pixel
// is a screen-space pattern of its own and a pixel's extra samples never change another's.
#include "sampling/samplers/poisson_sampler.h"

#include <cstdint>
#include <memory>

namespace pdrt {

// shape.samples_per_pixel rounded up to a power of two (2^m) is the block a pixel takes, the
// image's larger side rounded up (2^k) the Morton grid; pixels outside the image wrap onto it.
// Throws UsageError for 2k + m > 32 and for tables it cannot order (tiled pixel tables, a
// table size that is not a power of two, prefixes not stratified).
std::unique_ptr<Sampler> make_screen_poisson_sampler(uint64_t seed, const TableSet& tables, const SamplerShape& shape);

// The digits of z in bit positions [lo, hi) (base 4 from the top; when hi - lo is odd the last
// digit is the single bit lo), each permuted by a hash of key and of z's bits above it;
// the other bits 0. The sampler takes [m, bits), a pixel's digits. Digits of [0, bits) at once
// give the same as [m, bits) | [0, m) for bits - m even. Exposed for tests.
uint32_t scramble_digits(uint32_t z, int hi, int lo, uint64_t key);

}  // namespace pdrt
