#include "renderer/scene/pbrt/pbrt_build_context.h"

#include "renderer/scene/pbrt/pbrt_spectrum.h"
#include "sampling/core/errors.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

void PbrtBuild::fail(const PbrtLocation& at, const std::string& what) { throw InputError(at.str() + ": " + what); }

void PbrtBuild::report_unused(const std::vector<PbrtParam>& params) {
  for (const PbrtParam& p : params)
    if (!p.used) note(p.at, p.quoted() + " is not used by pdrt (ignored)");
}

void PbrtBuild::note(const PbrtLocation& at, const std::string& what, const std::string& kind) {
  std::string line = at.str() + ": " + what;
  if (strict) throw InputError(line + " [--strict]");
  auto [it, first] = note_kinds.try_emplace(kind.empty() ? what : kind, NoteKind{out.report.size(), 0, at});
  if (first) {
    out.report.push_back(line);
  } else {
    ++it->second.more;
    it->second.last = at;
  }
}

void PbrtBuild::finish_report() {
  for (const auto& [kind, k] : note_kinds)
    if (k.more > 0)
      out.report[k.line] += " (and " + std::to_string(k.more) + " more like it, the last at " + k.last.str() + ")";
}

void PbrtBuild::note_rgb(const PbrtLocation& at, const std::string& what) {
  note(at,
       what +
           ": pdrt multiplies colours per RGB channel where pbrt-v4 works per wavelength, so light it "
           "reflects differs in colour (by a few % for saturated colours; grey is exact)",
       "rgb");
}

void PbrtBuild::place(const PbrtLocation& at, Affine* transform, std::vector<MotionKey>* motion) {
  for (const Mat4& m : gs.cur.ctm.t)
    if (!m.affine()) fail(at, "the current transform is projective; shapes and lights need an affine one");
  if (!gs.moving()) {
    *transform = gs.cur.ctm.t[0].to_affine();
    return;
  }
  *transform = Affine{};
  motion->clear();
  for (int i = 0; i < 2; ++i) {
    double shear = 0;
    MotionKey k = decompose(gs.cur.ctm.t[i], &shear);
    if (shear > 1e-4)
      note(at, "the transform at time " + pbrt_number(gs.times[i]) +
                   " shears (dropped: pdrt's motion keys hold scale, rotation, translation)");
    k.time = float(gs.times[i]);
    motion->push_back(k);
  }
}

Vec3 PbrtBuild::color(const PbrtParams& ps, const std::string& name, Vec3 fallback, bool emission) {
  const PbrtParam* p = ps.find(name);
  if (!p) return fallback;
  const std::string type = pbrt_canonical_type(p->type);
  p->used = true;
  // Emission of any colour renders as pbrt-v4's on grey surfaces; a colour that reflects does not.
  auto reflected = [&](Vec3 c) {
    const float hi = std::max({c.x, c.y, c.z}), lo = std::min({c.x, c.y, c.z});
    if (!emission && hi - lo > 1e-3f * hi)
      note_rgb(p->at, p->quoted() + " (" + pbrt_number(c.x) + ", " + pbrt_number(c.y) + ", " + pbrt_number(c.z) +
                          " in linear sRGB) is not grey");
    return c;
  };
  if (type == "rgb") {
    if (p->numbers.size() != 3) fail(p->at, p->quoted() + " needs 3 values, got " + std::to_string(p->numbers.size()));
    Vec3 c{float(p->numbers[0]), float(p->numbers[1]), float(p->numbers[2])};
    for (int i = 0; i < 3; ++i)
      if (!(c[i] >= 0))
        fail(p->at, "\"" + p->type + " " + name + "\" must have components >= 0, got " + pbrt_number(c[i]));
    return reflected(c);
  }
  if (type == "blackbody") {
    if (p->numbers.size() != 1 || !(p->numbers[0] > 0))
      fail(p->at, "\"blackbody " + name + "\" takes one temperature > 0 (kelvin)");
    return reflected(blackbody_rgb(p->numbers[0]));
  }
  if (type == "spectrum") {
    if (!p->strings.empty()) {
      if (emission)
        if (std::optional<Vec3> c = named_illuminant_rgb(p->strings[0])) return *c;
      note(p->at, "named spectrum \"" + p->strings[0] + "\" for \"" + name + "\" is not supported (default used)");
      return fallback;
    }
    if (p->numbers.size() < 2 || p->numbers.size() % 2)
      fail(p->at, "\"spectrum " + name + "\" needs (wavelength, value) pairs");
    return reflected(sampled_spectrum_to_rgb(p->numbers, emission));
  }
  if (type == "float" && p->numbers.size() == 1) return Vec3(float(p->numbers[0]));
  if (type == "texture") {
    if (!bind_to) {
      note(p->at, "a texture for \"" + name + "\" is not supported here (default used)");
      return fallback;
    }
    if (auto t = texture_ref(*p, "spectrum")) bind_to->push_back({bind_param, *t});
    return fallback;
  }
  fail(p->at, p->quoted() + " must be rgb, spectrum, blackbody or a texture");
}

float PbrtBuild::positive(const PbrtParams& ps, const std::string& name, float fallback, bool allow_zero) {
  std::optional<double> v = ps.find_float(name);
  if (!v) return fallback;
  if (!(allow_zero ? *v >= 0 : *v > 0) || !std::isfinite(*v))
    fail(ps.find(name)->at,
         "\"float " + name + "\" must be " + (allow_zero ? ">= 0" : "> 0") + ", got " + pbrt_number(*v));
  return float(*v);
}

std::optional<int> PbrtBuild::texture_ref(const PbrtParam& p, const std::string& kind) {
  auto it = textures.find(kind + ":" + p.strings[0]);
  if (it == textures.end()) it = textures.find((kind == "float" ? "spectrum:" : "float:") + p.strings[0]);
  if (it == textures.end()) fail(p.at, "unknown texture \"" + p.strings[0] + "\"");
  if (it->second < 0) {
    note(p.at, "texture \"" + p.strings[0] + "\" is not supported (the default value is used)");
    return std::nullopt;
  }
  return it->second;
}

// A texture input of a checkerboard: a number, an rgb or a texture.
TextureInput PbrtBuild::texture_input(const PbrtParams& ps, const std::string& name, float fallback,
                                      const std::string& kind) {
  TextureInput in;
  in.value = Vec3(fallback);
  const PbrtParam* p = ps.find(name);
  if (!p) return in;
  if (pbrt_canonical_type(p->type) == "texture") {
    p->used = true;
    if (auto t = texture_ref(*p, kind)) in.texture = *t;
    return in;
  }
  in.value = color(ps, name, Vec3(fallback), false);
  return in;
}

int PbrtBuild::add_texture(TextureDesc t, const std::string& name, const PbrtLocation& at) {
  t.name = name;
  t.where = at.str();
  const long long cost = texture_node_cost(t, texture_cost);
  if (cost > kMaxTextureEvaluation)
    fail(at, "texture \"" + name + "\" evaluates " +
                 (cost >= (1LL << 40) ? std::string("more than 2^40") : std::to_string(cost)) +
                 " scale/mix/invert/power nodes per lookup (at most " + std::to_string(kMaxTextureEvaluation) + ")");
  out.scene.textures.push_back(std::move(t));
  texture_cost.push_back(cost);
  return int(out.scene.textures.size()) - 1;
}

int PbrtBuild::current_material() {
  if (gs.cur.material >= 0) return gs.cur.material;
  if (default_material < 0) {
    Material m;
    m.name = "pbrt default";
    m.type = MaterialType::Diffuse;
    m.albedo = Vec3(0.5f);
    out.scene.materials.push_back(m);
    default_material = int(out.scene.materials.size()) - 1;
  }
  return default_material;
}

}  // namespace pdrt
