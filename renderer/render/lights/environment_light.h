#pragma once
// The environment: radiance arriving from every direction, constant or an image
// (environment_map.h). A constant one is sampled uniformly over the sphere of directions, an
// image by its luminance x sin(theta) (or that less its mean, compensated). Beside the light
// BVH, its importance is what it delivers to a surface: pi x its (solid-angle mean) luminance.
#include "renderer/render/environment_map.h"
#include "renderer/render/light_bounds.h"
#include "renderer/render/lights/light_sample.h"
#include "renderer/scene/scene_desc.h"

#include <array>
#include <memory>

namespace pdrt {

struct EnvironmentLight {
  Vec3 constant{0.0f};                        // the constant environment (black with an image)
  std::shared_ptr<const EnvironmentMap> map;  // or the image (shared: a light is copied into the set)
  float irradiance = 0;                       // pi x (mean) luminance, 0 if it emits nothing

  EnvironmentLight() = default;
  // sampling: how next-event estimation samples an image (environment_map.h); whether a
  // constant environment is sampled at all is the light set's choice (lights_from_scene).
  explicit EnvironmentLight(const EnvironmentDesc& d, EnvironmentSampling sampling = EnvironmentSampling::Full);

  bool has_image() const { return map && !map->empty(); }
  // Whether rays that escape see any light, and the radiance from the unit direction w.
  bool visible() const { return has_image() || !is_black(constant); }
  Vec3 radiance(const Vec3& w) const { return has_image() ? map->radiance(w) : constant; }

  InfiniteLightBounds bounds() const { return {Vec3(0.0f), irradiance, false}; }
  bool sample(const Vec3& ref, float time, std::array<double, 2> u, LightSample* out) const;
  float pdf(const Vec3& w) const { return has_image() ? map->pdf(w) : 1.0f / (4 * kPi); }
};

}  // namespace pdrt
