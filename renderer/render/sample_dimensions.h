#pragma once
// The one table of which sampler stream each random decision of a camera sample reads: a
// family and a bounce salt (sampling/samplers/sampler.h). The bounce is a salt: per family, any
// int that no other decision of the same family uses. 2-D decisions:
//   film point                  Pixel, 0          (camera_sample.cpp)
//   lens point                  Lens, 0
//   light point at vertex d     Light, d          (path_integrator.cpp)
//   BSDF direction at vertex d  Gloss, d
// 1-D decisions, all in the time family:
//   shutter time                Time, 0
//   light choice at vertex d    Time, 1 + 3d
//   lobe choice at vertex d     Time, 2 + 3d
//   roulette at vertex d        Time, 3 + 3d
#include "sampling/samplers/sampler.h"

namespace pdrt {

inline constexpr int kSaltFilmPoint = 0;                                   // Family::Pixel
inline constexpr int kSaltLensPoint = 0;                                   // Family::Lens
inline constexpr int kSaltShutterTime = 0;                                 // Family::Time
inline constexpr int salt_light_point(int depth) { return depth; }         // Family::Light
inline constexpr int salt_bsdf_direction(int depth) { return depth; }      // Family::Gloss
inline constexpr int salt_light_pick(int depth) { return 1 + 3 * depth; }  // Family::Time
inline constexpr int salt_lobe(int depth) { return 2 + 3 * depth; }        // Family::Time
inline constexpr int salt_roulette(int depth) { return 3 + 3 * depth; }    // Family::Time

// Paths up to this depth read every decision from the streams PixelSampleState prepares per
// pixel sample (its kCachedSalts per family); deeper vertices ask the sampler directly (the
// same values, only slower).
inline constexpr int kCachedDepth = 16;
static_assert(salt_roulette(kCachedDepth) < PixelSampleState::kCachedSalts,
              "every time-family salt of a depth-16 path is cached");
static_assert(salt_light_point(kCachedDepth) < PixelSampleState::kCachedSalts &&
                  salt_bsdf_direction(kCachedDepth) < PixelSampleState::kCachedSalts,
              "every light and gloss salt of a depth-16 path is cached");

}  // namespace pdrt
