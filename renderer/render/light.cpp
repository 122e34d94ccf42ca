#include "renderer/render/light.h"

#include <algorithm>

namespace pdrt {

SceneLights lights_from_scene(const EmbreeScene& scene, const TextureSet& textures) {
  const SceneDesc& d = scene.desc();
  SceneLights out;
  out.first_light.assign(d.shapes.size(), -1);
  for (std::size_t i = 0; i < d.shapes.size(); ++i) {
    const ShapeDesc& s = d.shapes[i];
    const Material& m = d.materials[s.material];
    if (m.type != MaterialType::Emitter || is_black(m.radiance)) continue;
    out.first_light[i] = int64_t(out.lights.size());
    const AreaEmitter e{&scene, &textures, int(i), std::max(emitter_luminance(textures, m), 1e-6f)};
    if (s.kind == ShapeDesc::Kind::Sphere) {
      out.lights.push_back(SphereLight{e});
      continue;
    }
    for (std::size_t t = 0; t < scene.indices(int(i)).size() / 3; ++t) out.lights.push_back(TriangleLight{e, int(t)});
  }
  // Point and spot lights join the BVH after every shape's lights (so a shape's stay
  // contiguous); distant lights stay outside it, beside the environment.
  std::vector<Light> distant;
  for (const DeltaLightDesc& l : d.delta_lights) {
    const LightPlacement at{&l, d.camera.shutter_open, d.camera.shutter_close};
    if (l.kind == DeltaLightDesc::Kind::Point) {
      if (!is_black(l.intensity)) out.lights.push_back(PointLight{at});
    } else if (l.kind == DeltaLightDesc::Kind::Spot) {
      if (!is_black(l.intensity)) out.lights.push_back(SpotLight{at});
    } else if (!is_black(l.irradiance)) {
      distant.push_back(DistantLight{-l.direction, l.irradiance, std::max(luminance(l.irradiance), 1e-6f)});
    }
  }
  out.lights.insert(out.lights.end(), distant.begin(), distant.end());
  // Compensated: a constant environment takes no light samples, as pbrt-v4's
  // UniformInfiniteLight (BSDF sampling alone reaches it); an image is sampled from its
  // compensated distribution (environment_map.h).
  const EnvironmentSampling sampling = d.integrator.environment_sampling;
  out.environment = EnvironmentLight(d.environment, sampling);
  out.environment_sampled =
      out.environment.irradiance > 0 && (out.environment.has_image() || sampling == EnvironmentSampling::Full);
  if (out.environment_sampled) out.lights.push_back(out.environment);
  return out;
}

}  // namespace pdrt
