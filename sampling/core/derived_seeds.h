#pragma once
// Every seed pdrt derives from a user's seed, in one place: each purpose has its own salt, so
// that no two purposes collide by accident, and changing one changes the images it feeds (the
// salts are part of what makes a seed's images replayable). The samplers' per-stream hashes
// (sampler.cpp) start from sample_hash_seed.
#include "sampling/core/rng.h"  // mix64

#include <cstdint>

namespace pdrt {

// The sampler's streams: every (pixel, family, bounce) stream hashes from this.
inline uint64_t sample_hash_seed(uint64_t seed) { return mix64(seed ^ 0x70647274ull); }  // "pdrt"
// The keys of random walks inside one path vertex (PixelSampleState::walk_key).
inline uint64_t walk_key_seed(uint64_t seed) { return mix64(seed ^ 0x77616c6b6b6579ull); }  // "walkkey"
// The sampler whose samples decide when a pixel stops (adaptive "split").
inline uint64_t decider_seed(uint64_t seed) { return mix64(seed ^ 0x6465636964657273ull); }  // "deciders"
// The random part of McCool–Fiume rank thresholds (reconstruction "rank").
inline uint64_t rank_jitter_seed(uint64_t seed) { return mix64(seed ^ 0x72616e6b5f6a6974ull); }  // "rank_jit"
// compare's reference, and the seed of its second half (the first half uses the reference's).
inline uint64_t reference_seed(uint64_t seed) { return seed ^ 0x5eedc0ffee123457ull; }
inline uint64_t reference_half_seed(uint64_t reference) { return mix64(reference ^ 0x68616c6662ull); }  // "halfb"

}  // namespace pdrt
