#pragma once
// `zsobol`: Ahmed & Wonka 2020, "Screen-Space Blue-Noise Diffusion of Monte Carlo Sampling
// Error via Hierarchical Ordering of Pixels" (pbrt-v4's default sampler). Pixels are put in
// Morton (Z) order and each takes one aligned block of a single Owen-scrambled Sobol sequence
// per dimension; aligned blocks of a (0,2)-sequence are (0,m,2)-nets, so a pixel's samples are
// stratified and so are those of every 2^j x 2^j group of pixels around it, which moves the
// error of neighbouring pixels apart in the plane of samples: blue noise on screen. The
// base-4 digits of the Morton index are permuted, each by one of the 24 permutations picked
// by a hash of the digits above it and of the dimension (§4: a nested scramble of the pixel
// order), so the order differs per dimension and per seed while blocks stay aligned.
#include "sampling/samplers/sampler.h"

#include <cstdint>
#include <memory>

namespace pdrt {

// shape.samples_per_pixel rounded up to a power of two is the block a pixel takes; pixels
// outside the shape's image wrap onto it. Throws UsageError when Morton index and sample index need more than 32 bits
// together (the 32-bit fixed-point values see no more).
std::unique_ptr<Sampler> make_zsobol_sampler(uint64_t seed, const SamplerShape& shape);

// The Sobol index pixel (px, py)'s sample `index` takes for the dimension key `key`, below
// 2^(2 k + m) for 2^k >= the image's larger side and 2^m samples per pixel; exposed for tests.
uint32_t zsobol_sobol_index(uint32_t morton_and_sample, int bits, uint64_t key);

}  // namespace pdrt
