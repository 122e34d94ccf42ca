#pragma once
// Adaptive refinement (McCool–Fiume §5.1 / Cook §6): after a first round at min_spp (in
// progressive passes: progressive_passes.h), rounds
// that extend prefixes. A pixel whose error is above the threshold doubles its sample count
// (up to max_spp); its 3x3 neighbours refine with it, so edges are not left blocky. Samples
// already taken are never moved or discarded. Rounds go on until no pixel refines or the
// render is cancelled.
#include "renderer/render/render_films.h"
#include "renderer/render/render_region.h"
#include "renderer/render/tile_passes.h"
#include "renderer/scene/scene_desc.h"

#include <cstdint>
#include <functional>

namespace pdrt {

// Renders `ad`'s first pass and its refinement rounds; returns the rounds after the first.
// `quiet`: no progress line; `on_pass` (if set): called after each of round 0's passes.
int render_adaptive_rounds(const AdaptiveDesc& ad, const RenderRegion& region, RenderFilms& films, TilePasses& passes,
                           bool quiet, const std::function<void(int64_t)>& on_pass);

}  // namespace pdrt
