#pragma once
// The lights next-event estimation aims at (Cook §5.3 "light area" dimension): one struct per
// type in lights/ behind a closed variant, as pbrt-v4 keeps its lights (lights.h) apart from
// the light sampler that chooses among them (light_selector.h). Each has
//   bounds()  LightBounds for a light in the light BVH, InfiniteLightBounds for one beside it
//   sample(ref, time, u, out)  a direction toward it from ref at the normalised shutter time,
//             with its radiance and solid-angle pdf (the light-family pair u; delta lights
//             ignore it)
// and the area lights (which BSDF sampling can hit) pdf(ref, hit, time, pick).
//   TriangleLight     lights/triangle_light.h     one triangle of an emissive mesh
//   SphereLight       lights/sphere_light.h       an emissive sphere
//   PointLight        lights/point_light.h        delta, in the BVH
//   SpotLight         lights/spot_light.h         delta, in the BVH
//   DistantLight      lights/distant_light.h      delta, at infinity
//   EnvironmentLight  lights/environment_light.h  constant or image, at infinity
// A new light is a struct in its own file, one alternative in Light and the place it is made
// from the scene in lights_from_scene (light.cpp).
#include "renderer/render/lights/distant_light.h"
#include "renderer/render/lights/environment_light.h"
#include "renderer/render/lights/point_light.h"
#include "renderer/render/lights/sphere_light.h"
#include "renderer/render/lights/spot_light.h"
#include "renderer/render/lights/triangle_light.h"

#include <cstdint>
#include <variant>
#include <vector>

namespace pdrt {

using Light = std::variant<TriangleLight, SphereLight, PointLight, SpotLight, DistantLight, EnvironmentLight>;

struct SceneLights {
  // Light ids are the indices: one per emissive triangle or sphere in shape order, then the
  // point and spot lights, then the distant lights, then the environment if it emits and is
  // sampled (the lights in the BVH first, those beside it after). Lights of zero power are left out.
  std::vector<Light> lights;
  std::vector<int64_t> first_light;  // per shape: the id of its first light, or -1
  EnvironmentLight environment;      // what escaping rays see (black when there is none)
  // Whether the environment is the last of `lights` (IntegratorDesc::environment_sampling).
  bool environment_sampled = false;
};

// textures: the scene's, opened once (MaterialSet owns them); textured emitters read them.
SceneLights lights_from_scene(const EmbreeScene& scene, const TextureSet& textures);

}  // namespace pdrt
