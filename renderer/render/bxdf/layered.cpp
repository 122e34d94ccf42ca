#include "renderer/render/bxdf/layered.h"

#include "renderer/render/bxdf/henyey_greenstein.h"
#include "sampling/core/rng.h"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>

namespace pdrt {
namespace {

// The kinds of call, each its own stream for the same key and directions.
enum : uint64_t { kEvalStream = 0x6576616c, kPdfStream = 0x706466, kSampleStream = 0x73616d70 };

uint64_t walk_seed(uint64_t key, uint64_t kind, const Vec3& a, const Vec3& b) {
  uint64_t h = hash_combine(key, kind);
  for (const Vec3* v : {&a, &b})
    for (int k = 0; k < 3; ++k) h = hash_combine(h, std::bit_cast<uint32_t>((*v)[k]));
  return h;
}

// A uniform float in [0, 1) (a double rounded to float can reach 1).
float next(Rng& rng) { return std::min(float(rng.uniform()), 0x1.fffffep-1f); }

float power_heuristic(float a, float b) {
  float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0 ? a2 / (a2 + b2) : 0.0f;
}

Vec3 clamp01(Vec3 v) {
  for (int c = 0; c < 3; ++c) v[c] = std::clamp(v[c], 0.0f, 1.0f);
  return v;
}

bool usable(const LayerSample& s) { return !is_black(s.f) && s.pdf > 0 && s.wi.z != 0; }

}  // namespace

LayeredBxdf::LayeredBxdf(const CoatInterface& top, const LayerBase& bottom, const CoatLayers& layers, ExitMis exit_mis)
    : exit_mis_(layers.consistent_exit ? ExitMis::Consistent : exit_mis),
      top_(top),
      bottom_(bottom),
      thickness_(std::max(layers.thickness, FLT_MIN)),
      albedo_(clamp01(layers.albedo)),
      scatters_(!is_black(albedo_)),
      g_(std::clamp(layers.g, -1.0f, 1.0f)),
      max_depth_(layers.max_depth),
      samples_(std::max(1, layers.samples)) {}

// pbrt-v4's materials.cpp: roughness as alpha (pdrt's roughness^2), index 0 taken as 1,
// reflectances and the medium's albedo clamped to [0, 1], g to [-1, 1].
LayeredBxdf LayeredBxdf::coated_diffuse(const Material& m) {
  const float eta = m.ior > 0 ? m.ior : 1.0f;
  return LayeredBxdf(CoatInterface(eta, m.roughness * m.roughness), LayerBase::diffuse(clamp01(m.albedo)), m.layers);
}

LayeredBxdf LayeredBxdf::coated_conductor(const Material& m) {
  const float eta = m.ior > 0 ? m.ior : 1.0f;
  const LayerBase base = LayerBase::conductor(m.eta / eta, m.k / eta, m.base_roughness * m.base_roughness);
  return LayeredBxdf(CoatInterface(eta, m.roughness * m.roughness), base, m.layers);
}

float LayeredBxdf::exit_mis_pdf(const Vec3& w, const Vec3& wi) const {
  // pbrt-v4 weighs with the pdf of wi given the inner direction (outside measure); the
  // virtual light path samples the inner direction given wi (inside measure).
  return exit_mis_ == ExitMis::Pbrt ? top_.pdf(-w, wi, kLayerTransmit) : top_.pdf(wi, -w, kLayerTransmit);
}

float LayeredBxdf::tr(float dz, const Vec3& w) const {
  if (std::abs(dz) <= FLT_MIN) return 1.0f;
  return std::exp(-std::abs(dz / w.z));
}

Vec3 LayeredBxdf::eval(Vec3 wo, Vec3 wi, uint64_t key) const {
  if (wo.z < 0) wo = -wo, wi = -wi;  // two-sided
  // Transmission would leave through the opaque base: nothing.
  if (wo.z == 0 || wi.z <= 0) return Vec3(0.0f);
  Vec3 f(top_.f(wo, wi, Transport::Radiance) * float(samples_));
  Rng rng(walk_seed(key, kEvalStream, wo, wi));
  for (int s = 0; s < samples_; ++s) {
    // Enter through the top toward the base, and a virtual light path entering from wi.
    LayerSample wos, wis;
    float uc = next(rng), u1 = next(rng), u2 = next(rng);
    if (!top_.sample(wo, uc, u1, u2, Transport::Radiance, kLayerTransmit, &wos) || !usable(wos)) continue;
    uc = next(rng), u1 = next(rng), u2 = next(rng);
    if (!top_.sample(wi, uc, u1, u2, Transport::Importance, kLayerTransmit, &wis) || !usable(wis)) continue;
    f += walk_eval(wi, wos, wis, rng);
  }
  return f / float(samples_);
}

// One walk of pbrt-v4's f() from the top (exit interface, z = thickness) down, with the
// entering sample wos and the virtual light sample wis.
Vec3 LayeredBxdf::walk_eval(const Vec3& wi, const LayerSample& wos, const LayerSample& wis, Rng& rng) const {
  const HenyeyGreenstein phase(g_);
  const float exit_z = thickness_;
  Vec3 f(0.0f), beta = wos.f * (std::abs(wos.wi.z) / wos.pdf), w = wos.wi;
  float z = thickness_;
  for (int depth = 0; depth < max_depth_; ++depth) {
    if (depth > 3 && max_component(beta) < 0.25f) {
      float q = std::max(0.0f, 1.0f - max_component(beta));
      if (next(rng) < q) break;
      beta /= 1.0f - q;
    }
    if (!scatters_) {
      z = z == thickness_ ? 0.0f : thickness_;
      beta *= tr(thickness_, w);
    } else {
      // Distance to the next interaction along w (extinction 1): in the slab, the medium scatters.
      const float zp = z + (w.z > 0 ? 1.0f : -1.0f) * -std::log(1.0f - next(rng)) * std::abs(w.z);
      if (zp == z) continue;
      if (0 < zp && zp < thickness_) {
        // Light through the top along the virtual light path, MIS against the phase sample.
        float wt = top_.specular() ? 1.0f : power_heuristic(wis.pdf, phase.p(-w, -wis.wi));
        f += beta * albedo_ * (phase.p(-w, -wis.wi) * wt * tr(zp - exit_z, wis.wi) / wis.pdf) * wis.f;
        float u1 = next(rng), u2 = next(rng), ppdf;
        const Vec3 wn = phase.sample(-w, u1, u2, &ppdf);
        if (!(ppdf > 0) || wn.z == 0) continue;
        beta *= albedo_;  // p / pdf = 1
        w = wn, z = zp;
        if (w.z > 0 && !top_.specular()) {
          const float fexit = top_.f(-w, wi, Transport::Radiance);
          if (fexit > 0) {
            float exit_pdf = exit_mis_pdf(w, wi);
            f += beta * (tr(zp - exit_z, w) * fexit * power_heuristic(ppdf, exit_pdf));
          }
        }
        continue;
      }
      z = std::clamp(zp, 0.0f, thickness_);
    }
    LayerSample bs;
    float uc = next(rng), u1 = next(rng), u2 = next(rng);
    if (z == exit_z) {
      // Reflection off the underside of the top, back into the slab.
      if (!top_.sample(-w, uc, u1, u2, Transport::Radiance, kLayerReflect, &bs) || !usable(bs)) break;
      beta *= bs.f * (std::abs(bs.wi.z) / bs.pdf);
      w = bs.wi;
      continue;
    }
    // At the base: light through the top along the virtual light path, MIS against the base's sample.
    if (!bottom_.specular()) {
      float wt = top_.specular() ? 1.0f : power_heuristic(wis.pdf, bottom_.pdf(-w, -wis.wi));
      f += beta * bottom_.f(-w, -wis.wi) * wis.f * (std::abs(wis.wi.z) * wt * tr(thickness_, wis.wi) / wis.pdf);
    }
    if (!bottom_.sample(-w, u1, u2, &bs) || !usable(bs)) break;
    beta *= bs.f * (std::abs(bs.wi.z) / bs.pdf);
    w = bs.wi;
    if (!top_.specular()) {
      // The base's sample leaving through the top toward wi.
      const float fexit = top_.f(-w, wi, Transport::Radiance);
      if (fexit > 0) {
        float wt = bottom_.specular() ? 1.0f : power_heuristic(bs.pdf, exit_mis_pdf(w, wi));
        f += beta * (tr(thickness_, bs.wi) * fexit * wt);
      }
    }
  }
  return f;
}

float LayeredBxdf::pdf(Vec3 wo, Vec3 wi, uint64_t key) const {
  if (wo.z < 0) wo = -wo, wi = -wi;
  float sum = 0;
  if (wo.z > 0 && wi.z > 0) {
    sum = float(samples_) * top_.pdf(wo, wi, kLayerReflect);
    Rng rng(walk_seed(key, kPdfStream, wo, wi));
    for (int s = 0; s < samples_; ++s) {
      // Transmission-reflection-transmission: into the slab from wo and from wi, the base between.
      LayerSample wos, wis, rs;
      float uc = next(rng), u1 = next(rng), u2 = next(rng);
      bool in_o = top_.sample(wo, uc, u1, u2, Transport::Radiance, kLayerTransmit, &wos);
      uc = next(rng), u1 = next(rng), u2 = next(rng);
      bool in_i = top_.sample(wi, uc, u1, u2, Transport::Importance, kLayerTransmit, &wis);
      if (!in_o || !in_i || is_black(wos.f) || is_black(wis.f)) continue;
      if (top_.specular()) {
        sum += bottom_.pdf(-wos.wi, -wis.wi);
        continue;
      }
      uc = next(rng), u1 = next(rng), u2 = next(rng);
      if (!bottom_.sample(-wos.wi, u1, u2, &rs) || is_black(rs.f)) continue;
      if (bottom_.specular()) {
        sum += top_.pdf(-rs.wi, wi, kLayerBoth);
        continue;
      }
      // Both rough: the product of the pdfs estimated with MIS over which end is sampled.
      const float r_pdf = bottom_.pdf(-wos.wi, -wis.wi), t_pdf = top_.pdf(-rs.wi, wi, kLayerBoth);
      sum += power_heuristic(wis.pdf, r_pdf) * r_pdf + power_heuristic(rs.pdf, t_pdf) * t_pdf;
    }
  }
  // Mixed with a uniform pdf over the sphere, as pbrt-v4 does.
  return 0.1f / (4.0f * kPi) + 0.9f * sum / float(samples_);
}

bool LayeredBxdf::sample(Vec3 wo, float u1, float u2, float uc, BsdfSample* out, uint64_t key) const {
  *out = BsdfSample{};
  const Vec3 wo_given = wo;
  const bool flip = wo.z < 0;
  if (flip) wo = -wo;
  LayerSample bs;
  if (!top_.sample(wo, uc, u1, u2, Transport::Radiance, kLayerBoth, &bs) || !usable(bs)) return false;
  if (bs.transmission) {
    Rng rng(walk_seed(key, kSampleStream, wo, Vec3{uc, u1, u2}));
    if (!walk_sample(bs, rng, out)) return false;
  } else {
    out->wi = bs.wi;
    out->weight = bs.f * (std::abs(bs.wi.z) / bs.pdf);
    out->pdf = bs.pdf;
    out->delta = bs.specular;
  }
  if (flip) out->wi = -out->wi;
  // MIS sees pbrt-v4's pdf estimate; a delta path keeps its discrete probability.
  if (!out->delta) out->pdf = pdf(wo_given, out->wi, key);
  return true;
}

// pbrt-v4's Sample_f walk after the top transmitted `entered` into the slab: f and pdf multiply
// along the path until the top transmits it out.
bool LayeredBxdf::walk_sample(const LayerSample& entered, Rng& rng, BsdfSample* out) const {
  const HenyeyGreenstein phase(g_);
  Vec3 f = entered.f * std::abs(entered.wi.z), w = entered.wi;
  float pdf = entered.pdf, z = thickness_;
  bool specular = entered.specular;
  for (int depth = 0; depth < max_depth_; ++depth) {
    float rr = max_component(f) / pdf;
    if (depth > 3 && rr < 0.25f) {
      float q = std::max(0.0f, 1.0f - rr);
      if (next(rng) < q) return false;
      pdf *= 1.0f - q;
    }
    if (w.z == 0) return false;
    if (scatters_) {
      const float zp = z + (w.z > 0 ? 1.0f : -1.0f) * -std::log(1.0f - next(rng)) * std::abs(w.z);
      if (zp == z) return false;
      if (0 < zp && zp < thickness_) {
        float a = next(rng), b = next(rng), ppdf;
        const Vec3 wn = phase.sample(-w, a, b, &ppdf);
        if (!(ppdf > 0) || wn.z == 0) return false;
        f *= albedo_ * ppdf;
        pdf *= ppdf;
        specular = false;
        w = wn, z = zp;
        continue;
      }
      z = std::clamp(zp, 0.0f, thickness_);
    } else {
      z = z == thickness_ ? 0.0f : thickness_;
      f *= tr(thickness_, w);
    }
    LayerSample s;
    float uc = next(rng), u1 = next(rng), u2 = next(rng);
    bool ok =
        z == 0 ? bottom_.sample(-w, u1, u2, &s) : top_.sample(-w, uc, u1, u2, Transport::Radiance, kLayerBoth, &s);
    if (!ok || !usable(s)) return false;
    f *= s.f;
    pdf *= s.pdf;
    specular = specular && s.specular;
    w = s.wi;
    if (s.transmission) {
      // Out through the top (the base is opaque): a reflection of the layered BSDF.
      out->wi = w;
      out->weight = f * (std::abs(w.z) / pdf);
      out->pdf = pdf;
      out->delta = specular;
      return true;
    }
    f *= std::abs(s.wi.z);
  }
  return false;
}

}  // namespace pdrt
