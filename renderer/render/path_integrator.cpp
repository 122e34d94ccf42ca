#include "renderer/render/path_integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pdrt {

namespace {

float power_heuristic(float a, float b) {
  float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0 ? a2 / (a2 + b2) : 0.0f;
}

}  // namespace

PathIntegrator::PathIntegrator(const EmbreeScene& scene, const LightSet& lights, const MaterialSet& materials,
                               const IntegratorDesc& settings)
    : scene_(scene), lights_(lights), materials_(materials), settings_(settings) {
  if (settings.regularize && !materials.regularizes())
    throw std::logic_error("PathIntegrator: regularize needs a MaterialSet built with regularize");
  const auto& ms = scene.desc().materials;
  hits_can_emit_ = std::any_of(ms.begin(), ms.end(), [](const Material& m) { return m.type == MaterialType::Emitter; });
}

PathResult PathIntegrator::trace(Ray ray, const PixelSampleState& ps) const { return trace(ray, ps, nullptr, false); }

PathResult PathIntegrator::trace(Ray ray, const PixelSampleState& ps, const SurfaceHit& first, bool found) const {
  return trace(ray, ps, &first, found);
}

PathResult PathIntegrator::trace(Ray ray, const PixelSampleState& ps, const SurfaceHit* first, bool first_found) const {
  PathResult res;
  res.depth = std::numeric_limits<float>::infinity();
  Vec3 beta(1.0f);
  float eta_scale = 1;  // product of eta^2 over transmissions: beta * eta_scale is free of the 1/eta^2 radiance scaling
  float prev_pdf = 0;   // solid-angle pdf of the BSDF sample that produced `ray`
  bool prev_delta = true;      // camera rays and delta lobes: emitters hit are counted fully
  bool any_non_delta = false;  // the path scattered off a non-delta lobe (regularisation starts after it)
  Vec3 prev_p, prev_n;         // the previous vertex and its shading normal: light selection depends on them
  const float time = ray.time;
  for (int depth = 0;; ++depth) {
    SurfaceHit hit;
    bool found;
    const bool last = depth == settings_.max_depth && depth > 0;  // a vertex that can only emit
    if (last && !hits_can_emit_) {
      // The last vertex scatters nothing and no surface emits: only an escaping ray adds light
      // (none without an environment), and Embree's any-hit occlusion query costs less than the
      // nearest hit.
      if (!lights_.has_environment()) break;
      ++res.rays;
      if (scene_.occluded(ray)) break;
      found = false;
    } else {
      ++res.rays;
      if (depth == 0 && first) {
        found = first_found;
        if (found) hit = *first;
      } else {
        found = scene_.intersect(ray, &hit);
      }
    }
    if (!found) {
      const Vec3 env = lights_.has_environment() ? lights_.environment(ray.dir) : Vec3(0.0f);
      if (!is_black(env)) {
        // A BSDF-sampled ray that escapes: weighted against the environment's light pdf.
        float w = prev_delta ? 1.0f : power_heuristic(prev_pdf, lights_.environment_pdf(prev_p, prev_n, ray.dir));
        res.radiance += beta * env * w;
      }
      break;
    }
    // A surface that cannot emit needs no shading at the last vertex.
    if (last && scene_.desc().materials[std::size_t(scene_.material(hit.shape))].type != MaterialType::Emitter) break;
    const Vec3 wo_world = -ray.dir;
    const MaterialSet::Shading shading = materials_.at(hit, wo_world, time, settings_.regularize && any_non_delta);
    const Material& mat = *shading.material;
    const Bsdf& bsdf = shading.bsdf();
    if (depth == 0) {
      res.albedo = bsdf.albedo();
      res.normal = hit.ns;
      res.depth = hit.t;
    }
    if (mat.type == MaterialType::Emitter) {
      Vec3 le = lights_.emitted(hit);
      if (!is_black(le)) {
        float w = prev_delta ? 1.0f : power_heuristic(prev_pdf, lights_.pdf(prev_p, prev_n, hit, time));
        res.radiance += beta * le * w;
      }
      break;  // emitters do not scatter
    }
    if (depth + 1 > settings_.max_depth) break;

    // Shading frame: opaque surfaces shade on the side the ray came from; dielectrics keep
    // the outward normal so the BSDF can tell entering from leaving.
    const bool dielectric = mat.type == MaterialType::Dielectric;
    Vec3 ns = hit.ns, ng = hit.ng;
    if (!dielectric && !hit.front) ns = -ns, ng = -ng;
    Frame frame(ns);
    Vec3 wo = frame.to_local(wo_world);
    const uint64_t key = ps.walk_key(depth);  // a stochastic BSDF's random walks at this vertex

    // Next-event estimation (not for delta lobes: a light sample has zero BSDF value).
    if (!bsdf.is_delta() && !lights_.empty()) {
      LightSample ls;
      // One light: its pick number changes nothing, so it is not drawn.
      const float u_pick = lights_.pick_matters() ? float(ps.get_1d(Family::Time, salt_light_pick(depth))) : 0.0f;
      if (lights_.sample(hit.p, ns, time, u_pick, ps.get_2d(Family::Light, salt_light_point(depth)), &ls) &&
          !is_black(ls.radiance)) {
        Vec3 wi = frame.to_local(ls.wi);
        Vec3 f = bsdf.eval(wo, wi, key);
        // Light leaking through the geometric surface is rejected (shading normals).
        bool same_side = dielectric || dot(ls.wi, ng) > 0;
        if (!is_black(f) && same_side) {
          // Between two offset points: the ray neither re-hits this surface nor the light.
          const Ray shadow = ls.at_infinity ? spawn_ray(hit.point(), hit.ng, ls.wi, time)
                                            : spawn_ray_to(hit.point(), hit.ng, ls.x, ls.n, time);
          ++res.rays;
          if (!scene_.occluded(shadow)) {
            // A delta light (point, spot, distant) cannot be hit by BSDF sampling: weight 1.
            float w = ls.delta ? 1.0f : power_heuristic(ls.pdf, bsdf.pdf(wo, wi, key));
            res.radiance += beta * f * ls.radiance * (std::abs(wi.z) * w / ls.pdf);
          }
        }
      }
    }

    // BSDF sampling (Cook's gloss dimension).
    BsdfSample bs;
    // A value the lobe does not read is not drawn (a mirror's direction, a single lobe's choice).
    const float uc = bsdf.uses_lobe_choice() ? float(ps.get_1d(Family::Time, salt_lobe(depth))) : 0.5f;
    const Vec2 u = bsdf.uses_direction() ? ps.get_2d(Family::Gloss, salt_bsdf_direction(depth)) : Vec2{0.5, 0.5};
    if (!bsdf.sample(wo, float(u[0]), float(u[1]), uc, &bs, key)) break;
    Vec3 wi_world = frame.to_world(bs.wi);
    // Reflection must leave on the front of the geometric surface, transmission behind it
    // (a thin dielectric's straight-through transmission; a dielectric's side is its own).
    if (!dielectric && (bs.transmission ? dot(wi_world, ng) >= 0 : dot(wi_world, ng) <= 0)) break;
    beta *= bs.weight;
    if (is_black(beta) || !is_finite(beta)) break;
    prev_pdf = bs.pdf;
    prev_delta = bs.delta;
    any_non_delta = any_non_delta || !bs.delta;
    prev_p = hit.p, prev_n = ns;

    if (bs.transmission) eta_scale *= bs.eta * bs.eta;

    // Russian roulette (pbrt-v4): survive with probability max(beta * eta_scale), so a path
    // inside glass is not killed for the radiance compression at the interface; no floor,
    // so a path of throughput >= 1 always survives (a lossless furnace stays noise-free).
    if (depth + 1 >= settings_.rr_depth) {
      float q = std::max(0.0f, 1 - max_component(beta * eta_scale));
      if (float(ps.get_1d(Family::Time, salt_roulette(depth))) < q) break;
      beta /= 1 - q;
    }
    ray = spawn_ray(hit.point(), hit.ng, wi_world, time);
  }
  return res;
}

}  // namespace pdrt
