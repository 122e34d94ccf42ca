#include "renderer/scene/pbrt/pbrt_build_context.h"

#include "renderer/scene/pbrt/pbrt_spectrum.h"
#include "renderer/scene/scene_limits.h"

#include <algorithm>
#include <cmath>

// pbrt-v4's materials as pdrt's (docs/pbrt-import.md): diffuse, conductor, coateddiffuse,
// coatedconductor, dielectric, thindielectric, mix; interface bounds media only.

namespace pdrt {
namespace {

// "reflectance": an rgb/spectrum, or a texture bound to the material's albedo.
Vec3 albedo(PbrtBuild& b, const PbrtParams& ps, Material& m) {
  b.bind_to = &m.textures, b.bind_param = MaterialParam::Albedo;
  Vec3 a = b.color(ps, "reflectance", Vec3(0.5f), false);
  b.bind_to = nullptr;
  return a;
}

// pbrt-v4 roughness (alpha when remaproughness is false, else alpha = sqrt(roughness)) as
// pdrt's perceptual roughness (alpha = roughness^2): roughness^(1/4) under remapping, else
// roughness^(1/2). A texture is bound through a power texture of that exponent (after the
// mean of uroughness and vroughness, when they differ): the filtered pbrt value is remapped
// per hit, exactly as pbrt-v4 remaps its evaluated roughness texture.
// `prefix` names a layer's roughness ("interface.", "conductor."), bound to `param` when textured.
float roughness(PbrtBuild& b, const PbrtDirective& d, const PbrtParams& ps, Material& m, const std::string& prefix = "",
                MaterialParam param = MaterialParam::Roughness) {
  struct Rough {
    double value = 0;
    int texture = -1;
    TextureInput input() const {
      TextureInput in;
      in.value = Vec3(float(value)), in.texture = texture;
      return in;
    }
  };
  auto one = [&](const std::string& n) -> std::optional<Rough> {
    const PbrtParam* p = ps.find(n);
    if (!p) return std::nullopt;
    Rough r;
    if (pbrt_canonical_type(p->type) == "texture") {
      p->used = true;
      if (auto t = b.texture_ref(*p, "float")) r.texture = *t;  // else reported, 0 used
      return r;
    }
    r.value = *ps.find_float(n);
    if (!(r.value >= 0) || !std::isfinite(r.value))
      b.fail(p->at, "\"float " + n + "\" must be >= 0, got " + pbrt_number(r.value));
    return r;
  };
  std::optional<Rough> r = one(prefix + "roughness"), u = one(prefix + "uroughness"), v = one(prefix + "vroughness");
  const Rough ru = u ? *u : r.value_or(Rough{}), rv = v ? *v : r.value_or(Rough{});
  const bool remap = ps.get_bool("remaproughness", true);
  if (ru.texture < 0 && rv.texture < 0) {
    if (ru.value != rv.value)
      b.note(d.at, "anisotropic roughness (" + pbrt_number(ru.value) + ", " + pbrt_number(rv.value) +
                       ") is not supported (their mean used)");
    double rough = 0.5 * (ru.value + rv.value);
    double alpha = remap ? std::sqrt(rough) : rough;
    return float(std::min(1.0, std::sqrt(alpha)));
  }
  TextureInput mean = ru.input();
  if (ru.texture != rv.texture || (ru.texture < 0 && ru.value != rv.value)) {
    b.note(d.at, "anisotropic roughness (uroughness and vroughness differ) is not supported (their mean used)");
    TextureDesc t;
    t.kind = TextureDesc::Kind::Mix;
    t.tex1 = ru.input(), t.tex2 = rv.input(), t.amount.value = Vec3(0.5f);
    mean.texture = b.add_texture(std::move(t), "mean roughness of " + m.name, d.at);
  }
  TextureDesc t;
  t.kind = TextureDesc::Kind::Power;
  t.tex = mean;
  t.exponent = remap ? 0.25f : 0.5f;
  m.textures.push_back({param, b.add_texture(std::move(t), prefix + "roughness of " + m.name, d.at)});
  return 0;
}

// A conductor's eta or k: rgb, or pbrt-v4's named metal spectra for the metals pdrt has.
// The metals' spectra become RGB values (reported: pbrt-v4's Fresnel term is per wavelength).
Vec3 metal_param(PbrtBuild& b, const PbrtLocation& at, const PbrtParams& ps, const std::string& name, bool eta) {
  const PbrtParam* p = ps.find(name);
  const NamedMetal* cu = find_named_metal("Cu");  // pbrt-v4's default conductor is copper
  if (!p) {
    b.note_rgb(at, "the conductor's default \"" + name + "\" (pbrt-v4's copper spectrum) as three RGB values");
    return eta ? cu->eta : cu->k;
  }
  p->used = true;
  if (pbrt_canonical_type(p->type) == "spectrum" && !p->strings.empty()) {
    const std::string& s = p->strings[0];
    for (const char* metal : {"Au", "Ag", "Cu", "Al"})
      if (s == std::string("metal-") + metal + (eta ? "-eta" : "-k")) {
        b.note_rgb(p->at, "named spectrum \"" + s + "\" as three RGB values");
        return eta ? find_named_metal(metal)->eta : find_named_metal(metal)->k;
      }
    b.note(p->at, "named spectrum \"" + s + "\" is not supported (copper used)");
    return eta ? cu->eta : cu->k;
  }
  if (pbrt_canonical_type(p->type) == "float" && p->numbers.size() == 1) return Vec3(float(p->numbers[0]));
  p->used = false;
  return b.color(ps, name, eta ? cu->eta : cu->k, false);
}

float named_glass_ior(PbrtBuild& b, const PbrtParam& p) {
  static const std::map<std::string, float> kGlass = {
      {"glass-BK7", 1.5168f}, {"glass-BAF10", 1.6700f}, {"glass-FK51A", 1.4866f}, {"glass-LASF9", 1.8503f},
      {"glass-F5", 1.6034f},  {"glass-F10", 1.6200f},   {"glass-F11", 1.6209f}};
  if (!p.strings.empty()) {
    auto it = kGlass.find(p.strings[0]);
    if (it != kGlass.end()) return it->second;
    b.note(p.at, "named spectrum \"" + p.strings[0] + "\" is not supported (1.5 used)");
    return 1.5f;
  }
  b.note(p.at, "a spectrally varying index is not supported (its value nearest 550 nm used)");
  double best = 1.5, dist = 1e30;
  for (size_t i = 0; i + 1 < p.numbers.size(); i += 2)
    if (std::abs(p.numbers[i] - 550) < dist) dist = std::abs(p.numbers[i] - 550), best = p.numbers[i + 1];
  if (!(best > 0)) b.fail(p.at, "the index of refraction must be > 0");
  return float(best);
}

// pbrt-v4's named glasses at the sodium d line (587.6 nm): pdrt's dielectric takes one index.
// "eta" of a dielectric or a coat: a number (default 1.5), a named glass or a spectrum.
float index_of_refraction(PbrtBuild& b, const PbrtParams& ps, const std::string& name = "eta") {
  const PbrtParam* e = ps.find(name);
  if (!e || pbrt_canonical_type(e->type) != "spectrum") return b.positive(ps, name, 1.5f);
  e->used = true;
  return named_glass_ior(b, *e);
}

// A conductor's "eta" and "k" (pbrt-v4's copper by default) or "reflectance" (F0 = r for eta = 1,
// k = 2 sqrt(r) / sqrt(1 - r), as pbrt-v4 does; a texture binds the same mapping per hit).
// pbrt-v4 refuses both; a coated conductor's are "conductor.eta" and "conductor.k" beside
// "reflectance".
void conductor_index(PbrtBuild& b, const PbrtLocation& at, const PbrtParams& ps, const std::string& pre, Material& m) {
  if (const PbrtParam* refl = ps.find("reflectance")) {
    for (const std::string& n : {pre + "eta", pre + "k"})
      if (ps.has(n)) b.fail(refl->at, "\"reflectance\" cannot be given with \"" + n + "\" (pbrt-v4 refuses both)");
    b.bind_to = &m.textures, b.bind_param = MaterialParam::Reflectance;
    Vec3 r = b.color(ps, "reflectance", Vec3(0.0f), false);
    b.bind_to = nullptr;
    conductor_from_reflectance(r, &m);
    return;
  }
  m.eta = metal_param(b, at, ps, pre + "eta", true);
  m.k = metal_param(b, at, ps, pre + "k", false);
}

// A constant float parameter of a layered material; a texture is reported and the default used.
std::optional<double> layer_float(PbrtBuild& b, const PbrtParams& ps, const std::string& name) {
  const PbrtParam* p = ps.find(name);
  if (!p) return std::nullopt;
  if (pbrt_canonical_type(p->type) == "texture") {
    p->used = true;
    b.note(p->at, "a texture for \"" + name + "\" is not supported (its default used)");
    return std::nullopt;
  }
  std::optional<double> v = ps.find_float(name);
  if (v && !std::isfinite(*v)) b.fail(p->at, "\"float " + name + "\" must be finite, got " + pbrt_number(*v));
  return v;
}

// The slab between a layered material's interfaces: pbrt-v4's thickness, albedo, g, maxdepth
// and nsamples, with its defaults (CoatLayers).
CoatLayers coat_layers(PbrtBuild& b, const PbrtParams& ps) {
  CoatLayers l;
  if (std::optional<double> t = layer_float(b, ps, "thickness")) {
    if (!(*t >= 0)) b.fail(ps.find("thickness")->at, "\"float thickness\" must be >= 0, got " + pbrt_number(*t));
    l.thickness = float(*t);
  }
  l.albedo = b.color(ps, "albedo", Vec3(0.0f), false);
  if (max_component(l.albedo) > 1)
    b.note(ps.find("albedo")->at, "the medium's \"albedo\" above 1 is clamped to 1 (as pbrt-v4 does)");
  if (std::optional<double> g = layer_float(b, ps, "g")) {
    if (std::abs(*g) > 1) b.note(ps.find("g")->at, "\"float g\" outside [-1, 1] is clamped (as pbrt-v4 does)");
    l.g = float(std::clamp(*g, -1.0, 1.0));
  }
  auto count = [&](const char* name, long long lo, long long hi, int fallback) {
    std::optional<int64_t> v = ps.find_int(name);
    if (!v) return fallback;
    if (*v < lo || *v > hi)
      b.fail(ps.find(name)->at, std::string("\"integer ") + name + "\" must be in [" + std::to_string(lo) + ", " +
                                    std::to_string(hi) + "], got " + std::to_string(*v));
    return int(*v);
  };
  l.max_depth = count("maxdepth", 0, kMaxLayerDepth, l.max_depth);
  l.samples = count("nsamples", 1, kMaxLayerSamples, l.samples);
  return l;
}

// Returns the material's index, or -2 for "interface" (a medium boundary, no surface).
int material(PbrtBuild& b, const PbrtDirective& d, const std::string& type, const PbrtParams& ps,
             const std::string& name) {
  Material m;
  m.name = name;
  // pbrt-v4's microfacet lobes lose the energy of multiple scattering; pdrt's compensation
  // only where the file asks for it with a pdrt parameter.
  m.energy_compensation = ps.get_bool("pdrt:energycompensation", false);
  for (const char* k : {"displacement", "normalmap"})
    if (const PbrtParam* p = ps.find(k)) {
      p->used = true;
      b.note(p->at, std::string("\"") + k + "\" is not supported (ignored)");
    }
  if (type == "" || type == "none" || type == "interface") return -2;
  if (type == "diffuse") {
    m.type = MaterialType::Diffuse;
    m.albedo = albedo(b, ps, m);
  } else if (type == "conductor") {
    m.type = MaterialType::Conductor;
    m.roughness = roughness(b, d, ps, m);
    conductor_index(b, d.at, ps, "", m);
  } else if (type == "coateddiffuse") {
    // pbrt-v4's CoatedDiffuseBxDF: the random walk through the layers (render/bxdf/layered.h).
    m.type = MaterialType::CoatedDiffuse;
    m.layered = true;
    m.albedo = albedo(b, ps, m);
    m.roughness = roughness(b, d, ps, m);
    m.ior = index_of_refraction(b, ps, "eta");
    m.layers = coat_layers(b, ps);
  } else if (type == "coatedconductor") {
    // pbrt-v4's CoatedConductorBxDF: a dielectric interface over a conductor, the same walk.
    m.type = MaterialType::CoatedConductor;
    m.layered = true;
    m.roughness = roughness(b, d, ps, m, "interface.");
    m.base_roughness = roughness(b, d, ps, m, "conductor.", MaterialParam::BaseRoughness);
    m.ior = index_of_refraction(b, ps, "interface.eta");
    conductor_index(b, d.at, ps, "conductor.", m);
    m.layers = coat_layers(b, ps);
  } else if (type == "dielectric") {
    m.type = MaterialType::Dielectric;
    m.albedo = Vec3(1.0f);
    m.ior = index_of_refraction(b, ps);
    m.roughness = roughness(b, d, ps, m);
  } else if (type == "thindielectric") {
    m.type = MaterialType::ThinDielectric;  // pbrt-v4's ThinDielectricBxDF: smooth only
    m.albedo = Vec3(1.0f);
    m.ior = index_of_refraction(b, ps);
  } else if (type == "mix") {
    // pbrt-v4's MixMaterial: two named materials, defined before, and the probability of the
    // second (amount <= 0 and >= 1 choose one outright, as pbrt-v4 does).
    m.type = MaterialType::Mix;
    const PbrtParam* p = ps.find("materials");
    if (!p || pbrt_canonical_type(p->type) != "string" || p->strings.size() != 2)
      b.fail(p ? p->at : d.at, "a \"mix\" material needs \"string materials\" with two named materials");
    p->used = true;
    for (size_t i = 0; i < 2; ++i) {
      auto it = b.gs.named_materials.find(p->strings[i]);
      if (it == b.gs.named_materials.end())
        b.fail(p->at, "unknown named material \"" + p->strings[i] + "\" in \"materials\"");
      if (it->second == -2)
        b.fail(p->at, "a mix of \"" + p->strings[i] + "\" (an interface, no surface) is not supported");
      m.mix[i] = it->second;
    }
    if (const PbrtParam* a = ps.find("amount"); a && pbrt_canonical_type(a->type) == "texture") {
      a->used = true;
      if (auto t = b.texture_ref(*a, "float")) m.textures.push_back({MaterialParam::Amount, *t});
    } else if (std::optional<double> v = ps.find_float("amount")) {
      if (!std::isfinite(*v)) b.fail(ps.find("amount")->at, "\"float amount\" must be finite");
      m.amount = float(std::clamp(*v, 0.0, 1.0));
    }
  } else {
    b.note(d.at, "material \"" + type + "\" is not supported (diffuse 0.5 used)");
    for (const PbrtParam& p : ps.list) p.used = true;
    m.type = MaterialType::Diffuse;
    m.albedo = Vec3(0.5f);
  }
  b.out.scene.materials.push_back(m);
  return int(b.out.scene.materials.size()) - 1;
}

}  // namespace

void translate_pbrt_material(PbrtBuild& b, const PbrtDirective& d) {
  PbrtAttributes& cur = b.gs.cur;
  switch (d.kind) {
    case PbrtDirectiveKind::Material: {
      int m = material(b, d, d.strings[0], d.params, "material at " + d.at.str());
      cur.interface = m == -2;
      cur.material = m == -2 ? -1 : m;
      return;
    }
    case PbrtDirectiveKind::MakeNamedMaterial: {
      std::optional<std::string> type = d.params.find_string("type");
      if (!type) b.fail(d.at, "MakeNamedMaterial \"" + d.strings[0] + "\" needs \"string type\"");
      b.gs.named_materials[d.strings[0]] = material(b, d, *type, d.params, d.strings[0]);
      return;
    }
    case PbrtDirectiveKind::NamedMaterial: {
      auto it = b.gs.named_materials.find(d.strings[0]);
      if (it == b.gs.named_materials.end()) b.fail(d.at, "unknown named material \"" + d.strings[0] + "\"");
      cur.interface = it->second == -2;
      cur.material = it->second == -2 ? -1 : it->second;
      return;
    }
    default:
      b.fail(d.at, "directive " + d.name + " is not a material");
  }
}

}  // namespace pdrt
