#pragma once
// The ranges of values a scene file and the command line may both set, defined once so the
// two agree (docs/scene-format.md and `pdrt render --help` quote them).
#include "sampling/core/int_range.h"

#include <cstdint>

namespace pdrt {

// film.width / film.height, --width / --height.
inline constexpr IntRange kFilmSizeRange{1, 65536};

// sampler.spp, sampler.adaptive.min_spp / max_spp, --spp, --min-spp, --max-spp,
// --reference-spp. 2^24: the `samples` AOV counts in float, exact only up to 2^24, and no
// pdrt reference needs more than 2^16 (compare's default reference is 4096).
inline constexpr IntRange kSppRange{1, uint64_t(1) << 24};

// sampler.seed, --seed: any 64-bit value.
inline constexpr IntRange kSeedRange{0, UINT64_MAX};

// A layered material's max_depth and samples (pbrt-v4's maxdepth, nsamples) in the scene file
// and the pbrt importer: bounds on the work of one BSDF evaluation (samples x max_depth events).
inline constexpr long long kMaxLayerDepth = 1000;
inline constexpr long long kMaxLayerSamples = 256;

}  // namespace pdrt
