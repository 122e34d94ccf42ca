#pragma once
// Only rank 0 of a distributed render prints warnings (sampling/core/warnings.h); the other
// ranks' held lines (a sampler's about a pixel only they rendered) go to it after the render,
// each kind printed once.
#include "renderer/render/process_group.h"

namespace pdrt {

// Collective: every rank hands its held warnings to rank 0, which prints them.
void relay_held_warnings(const ProcessGroup& group);

}  // namespace pdrt
