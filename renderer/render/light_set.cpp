#include "renderer/render/light_set.h"

#include <stdexcept>
#include <type_traits>

namespace pdrt {

LightSet::LightSet(const EmbreeScene& scene, const TextureSet& textures) : scene_(scene), textures_(textures) {
  SceneLights s = lights_from_scene(scene, textures);
  lights_ = std::move(s.lights);
  first_light_ = std::move(s.first_light);
  environment_ = std::move(s.environment);
  environment_sampled_ = s.environment_sampled;
  environment_id_ = lights_.size() - (environment_sampled_ ? 1 : 0);
  std::vector<LightBounds> bounded;
  std::vector<InfiniteLightBounds> infinite;
  bounded.reserve(lights_.size());
  for (const Light& l : lights_)
    std::visit(
        [&](const auto& light) {
          const auto b = light.bounds();
          if constexpr (std::is_same_v<std::decay_t<decltype(b)>, LightBounds>) {
            if (!infinite.empty()) throw std::logic_error("lights_from_scene: a bounded light after one at infinity");
            bounded.push_back(b);
          } else {
            infinite.push_back(b);
          }
        },
        l);
  selector_ = LightSelector(bounded, std::move(infinite));
}

bool LightSet::sample(const Vec3& ref, const Vec3& n, float time, float u_pick, std::array<double, 2> u,
                      LightSample* out) const {
  std::size_t id;
  float pick;
  if (!selector_.select(ref, n, u_pick, &id, &pick)) return false;
  if (!std::visit([&](const auto& l) { return l.sample(ref, time, u, out); }, lights_[id])) return false;
  out->pdf *= pick;
  return out->pdf > 0;
}

float LightSet::pdf(const Vec3& ref, const Vec3& n, const SurfaceHit& hit, float time) const {
  // Emitters inside instances are not among the lights: BSDF sampling alone reaches them (weight 1).
  if (hit.instance >= 0 || std::size_t(hit.shape) >= first_light_.size()) return 0;
  const int64_t first = first_light_[hit.shape];
  if (first < 0) return 0;
  if (const auto* sphere = std::get_if<SphereLight>(&lights_[std::size_t(first)]))
    return sphere->pdf(ref, hit, time, selector_.select_pmf(ref, n, std::size_t(first)));
  const std::size_t id = std::size_t(first + hit.prim);
  return std::get<TriangleLight>(lights_[id]).pdf(ref, hit, time, selector_.select_pmf(ref, n, id));
}

float LightSet::environment_pdf(const Vec3& ref, const Vec3& n, const Vec3& w) const {
  if (!environment_sampled_) return 0.0f;
  return selector_.select_pmf(ref, n, environment_id_) * environment_.pdf(w);
}

Vec3 LightSet::emitted(const SurfaceHit& hit) const {
  const Material& m = scene_.desc().materials[scene_.material(hit.shape)];
  if (m.type != MaterialType::Emitter) return Vec3(0.0f);
  return (hit.front || m.two_sided) ? emitter_radiance(scene_, textures_, m, hit) : Vec3(0.0f);
}

}  // namespace pdrt
