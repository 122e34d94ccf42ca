#include "renderer/scene/scene_loader.h"

#include "renderer/scene/pbrt/pbrt_scene_builder.h"

#include "sampling/core/errors.h"
#include "sampling/core/printable.h"
#include "sampling/core/warnings.h"
#include "sampling/samplers/sampler_names.h"
#include "renderer/scene/asset_path.h"
#include "renderer/scene/crop_window.h"
#include "renderer/scene/environment_image.h"
#include "renderer/scene/json_document.h"
#include "renderer/scene/obj_loader.h"
#include "renderer/scene/render_settings.h"
#include "renderer/scene/scene_limits.h"
#include "renderer/scene/text_file.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace pdrt {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

class SceneParser {
 public:
  SceneParser(const JsonDocument& doc, fs::path dir) : doc_(doc), root_(doc.root()), dir_(std::move(dir)) {}
  SceneDesc parse();

 private:
  void camera(const JsonObject& o);
  void film(const JsonObject& o);
  void projection(const JsonObject& camera);  // type, ortho_height, screen_window
  void crop_window(const JsonNode& n);
  void sampler(const JsonObject& o);
  void integrator(const JsonObject& o);
  void textures(const JsonNode& n);
  TextureInput texture_input(const JsonNode& n, int from);
  // A scale or mix texture's input: a number or [r, g, b] (components >= 0), or a texture's name.
  TextureInput texture_input_non_negative(const JsonNode& n, int from);
  void mix_materials(const std::vector<std::pair<int, JsonNode>>& mixes);
  int texture_named(const JsonNode& n) const;
  // A material parameter that is a value or the name of a texture (docs/scene-format.md,
  // "textures"): a value goes to `field`, a name to m.textures. One call per parameter.
  void textured_color(const JsonNode& n, Material& m, MaterialParam p, Vec3& field) const;
  void textured_unit(const JsonNode& n, Material& m, MaterialParam p, float& field) const;
  void materials(const JsonNode& n);
  void conductor_index(const JsonNode& mn, const JsonObject& o, Material& m) const;
  void coat_layers(const JsonObject& o, Material& m) const;
  // `prototype` >= 0: the objects of that prototype (no instances, motion or emitters).
  void objects(const JsonNode& n, int prototype = -1);
  void prototypes(const JsonNode& n);
  void instance(const JsonNode& on, const JsonObject& o);
  void refuse_emitter(const JsonNode& at, int material, int prototype) const;
  void lights(const JsonNode& n);
  void delta_light(const JsonNode& ln, const JsonObject& o, const std::string& type);
  void environment_light(const JsonNode& ln, const JsonObject& o);
  void load_objs();

  std::pair<float, float> shutter() const { return {scene_.camera.shutter_open, scene_.camera.shutter_close}; }
  int material_named(const JsonNode& n) const;
  Affine transform(const JsonNode& n) const;
  Affine rotation(const JsonNode& n) const;
  Vec3 scale(const JsonNode& n) const;
  // `sphere`: a key may scale only uniformly (Embree would make an ellipsoid of the instance,
  // while light sampling and the static case keep a sphere).
  std::vector<MotionKey> motion(const JsonNode& n, bool sphere) const;
  void check_time(const JsonNode& t, float previous, bool first) const;
  MeshData quad(const JsonObject& o);
  void keep_triangles(MeshData& mesh, const JsonNode& where);
  void place(ShapeDesc& s, const JsonObject& o, const std::string& where) const;

  const JsonDocument& doc_;
  JsonNode root_;
  fs::path dir_;
  SceneDesc scene_;
  std::map<std::string, int> material_index_;
  std::map<std::string, int> texture_index_;
  std::vector<std::vector<std::pair<int, JsonNode>>> texture_refs_;  // per texture: (texture it uses, where)

  struct PendingObj {   // OBJ files load after the whole JSON is validated
    size_t shape_slot;  // where in scene_.shapes its parts go
    fs::path path;
    JsonNode file;
    int material;  // -1: the MTL's
    ShapeDesc placement;
    int prototype = -1;  // >= 0: its parts go to that prototype, at shape_slot of its shapes
  };
  std::map<std::string, int> prototype_index_;
  std::vector<PendingObj> pending_;
};

SceneDesc SceneParser::parse() {
  JsonObject top(root_);
  top.allow({"camera", "film", "sampler", "integrator", "textures", "materials", "objects", "lights", "prototypes"});
  camera(top.require("camera").object());
  film(top.require("film").object());
  if (auto n = top.get("sampler")) sampler(n->object());
  if (auto n = top.get("integrator")) integrator(n->object());
  if (auto n = top.get("textures")) textures(*n);
  if (auto n = top.get("materials")) materials(*n);
  if (auto n = top.get("prototypes")) prototypes(*n);
  if (auto n = top.get("objects")) objects(*n);
  if (auto n = top.get("lights")) lights(*n);
  load_objs();
  return std::move(scene_);
}

void SceneParser::camera(const JsonObject& o) {
  o.allow({"position", "look_at", "up", "vfov_deg", "aperture_radius", "focus_distance", "aperture_blades",
           "aperture_rotation_deg", "shutter", "motion", "flip_x", "type", "ortho_height", "screen_window"});
  CameraDesc& c = scene_.camera;
  JsonNode pos = o.require("position"), look = o.require("look_at");
  c.position = pos.vec3();
  c.look_at = look.vec3();
  std::optional<JsonNode> up = o.get("up");
  if (up) c.up = up->nonzero_vec3();
  if (up && !std::isfinite(length(c.up))) up->fail_got("is too long to normalise in float");
  auto check_view = [&](const Vec3& p, const Vec3& l, const JsonNode& at_look) {
    Vec3 d = l - p;
    if (is_black(d)) at_look.fail_got("must differ from the position");
    if (!std::isfinite(length(d))) at_look.fail_got("is too far from the position for float arithmetic");
    if (length(cross(normalize(c.up), normalize(d))) < 1e-6f) {
      if (up) up->fail_got("must not be parallel to look_at - position");
      at_look.fail_got("makes the view direction parallel to camera.up (set \"up\")");
    }
  };
  check_view(c.position, c.look_at, look);
  if (auto n = o.get("vfov_deg")) {
    c.vfov_deg = n->number();
    if (!(c.vfov_deg > 0 && c.vfov_deg < 180)) n->fail_got("must be in (0, 180)");
  }
  if (auto n = o.get("aperture_radius")) c.aperture_radius = n->non_negative();
  c.focus_distance = length(c.look_at - c.position);
  if (auto n = o.get("focus_distance")) c.focus_distance = n->positive();
  if (auto n = o.get("aperture_blades")) {
    c.aperture_blades = int(n->integer(0, 1000));
    if (c.aperture_blades == 1 || c.aperture_blades == 2) n->fail_got("must be 0 (circle) or >= 3");
  }
  if (auto n = o.get("aperture_rotation_deg")) c.aperture_rotation_deg = n->number();
  if (auto n = o.get("flip_x")) c.flip_x = n->boolean();
  projection(o);
  if (auto n = o.get("shutter")) {
    if (!n->value().is_array() || n->value().size() != 2) n->fail_got("must be [open, close]");
    c.shutter_open = n->at(0).number();
    c.shutter_close = n->at(1).number();
    if (c.shutter_open > c.shutter_close) n->fail_got("must have open <= close");
  }
  if (auto n = o.get("motion")) {
    size_t count = n->array_size(2);
    for (size_t i = 0; i < count; ++i) {
      JsonObject k = n->at(i).object();
      k.allow({"time", "position", "look_at"});
      CameraKey key;
      JsonNode t = k.require("time");
      check_time(t, i ? c.motion.back().time : 0, i == 0);
      key.time = t.number();
      key.position = k.require("position").vec3();
      JsonNode kl = k.require("look_at");
      key.look_at = kl.vec3();
      check_view(key.position, key.look_at, kl);
      c.motion.push_back(key);
    }
  }
}

namespace {

// [x0, x1, y0, y1] of finite numbers with x0 < x1 and y0 < y1.
std::array<float, 4> window(const JsonNode& n) {
  if (!n.value().is_array() || n.value().size() != 4) n.fail_got("must be [x0, x1, y0, y1]");
  std::array<float, 4> w;
  for (int i = 0; i < 4; ++i) w[i] = n.at(i).number();
  if (!(w[0] < w[1])) n.fail_got("must have x0 < x1");
  if (!(w[2] < w[3])) n.fail_got("must have y0 < y1");
  return w;
}

}  // namespace

void SceneParser::projection(const JsonObject& o) {
  CameraDesc& c = scene_.camera;
  std::optional<JsonNode> type = o.get("type"), height = o.get("ortho_height");
  if (type && type->choice({"perspective", "orthographic"}) == "orthographic")
    c.projection = CameraDesc::Projection::Orthographic;
  if (height) {
    if (c.projection != CameraDesc::Projection::Orthographic)
      height->fail_key("needs \"type\": \"orthographic\" (the perspective camera's extent is vfov_deg)");
    c.ortho_height = height->positive();
  }
  if (auto n = o.get("screen_window")) {
    c.screen_window = window(*n);
    c.has_screen_window = true;
    // Past this a ray's direction (or its extent) overflows float arithmetic.
    for (float v : c.screen_window)
      if (!(std::abs(v) <= 1e6f)) n->fail_got("must have every bound within [-1e6, 1e6]");
  }
}

void SceneParser::crop_window(const JsonNode& n) {
  FilmDesc& f = scene_.film;
  std::array<float, 4> w = window(n);
  for (float v : w)
    if (!(v >= 0 && v <= 1)) n.fail_got("must lie within [0, 1] (fractions of the film, y down)");
  f.crop_window = w;
  if (std::string p = crop_window_problem(f); !p.empty()) n.fail_got(p);
}

void SceneParser::check_time(const JsonNode& t, float previous, bool first) const {
  float time = t.number();
  auto [open, close] = shutter();
  if (time < open || time > close) {
    std::ostringstream s;
    s << "must be within the shutter [" << open << ", " << close << "]";
    t.fail_got(s.str());
  }
  if (!first && !(time > previous)) {
    std::ostringstream s;
    s << "must be greater than the previous key's time (" << previous << ")";
    t.fail_got(s.str());
  }
}

void SceneParser::film(const JsonObject& o) {
  o.allow({"width", "height", "filter", "exposure", "crop_window"});
  FilmDesc& f = scene_.film;
  JsonNode width = o.require("width");
  f.width = int(width.integer_in(kFilmSizeRange));
  f.size_where = width.where() + "/height";
  f.height = int(o.require("height").integer_in(kFilmSizeRange));
  if (auto n = o.get("exposure")) f.exposure = n->number();
  if (auto n = o.get("crop_window")) crop_window(*n);
  if (auto n = o.get("filter")) {
    JsonObject fo = n->object();
    if (auto old = fo.get("selection"))
      old->fail_key(std::string("was replaced by \"reconstruction\": \"") +
                    reconstruction_name(Reconstruction::Importance) + "\" (default), \"" +
                    reconstruction_name(Reconstruction::Splat) + "\" or \"" +
                    reconstruction_name(Reconstruction::Rank) + "\"");
    fo.allow({"type", "radius", "sigma", "reconstruction"});
    std::string type = "gaussian";
    if (auto t = fo.get("type")) type = t->choice({"box", "tent", "gaussian", "mitchell"});
    static const std::map<std::string, std::pair<FilterType, float>> kinds = {
        {"box", {FilterType::Box, 0.5f}},
        {"tent", {FilterType::Tent, 1.0f}},
        {"gaussian", {FilterType::Gaussian, 1.5f}},
        {"mitchell", {FilterType::Mitchell, 2.0f}}};
    std::tie(f.filter.type, f.filter.radius) = kinds.at(type);
    if (auto r = fo.get("radius")) f.filter.radius = r->positive();
    if (auto s = fo.get("sigma")) {
      if (f.filter.type != FilterType::Gaussian)
        s->fail_key("is a parameter of the \"gaussian\" filter only, not of \"" + type + "\"");
      f.filter.sigma = s->positive();
    }
    if (auto m = fo.get("reconstruction")) f.filter.reconstruction = m->choice(kReconstructionNames);
  }
}

void SceneParser::sampler(const JsonObject& o) {
  o.allow({"type", "spp", "seed", "adaptive"});
  SamplerDesc& s = scene_.sampler;
  if (auto n = o.get("type")) s.type = sampler_name(n->choice(kSamplerNames)), s.type_where = n->where();
  if (auto n = o.get("spp")) s.spp = int(n->integer_in(kSppRange));
  if (auto n = o.get("seed")) s.seed = n->integer_in(kSeedRange);
  if (auto n = o.get("adaptive")) {
    JsonObject a = n->object();
    a.allow({"min_spp", "max_spp", "threshold", "metric", "variance", "decision"});
    s.adaptive.enabled = true;
    auto min_n = a.get("min_spp"), max_n = a.get("max_spp");
    if (min_n) s.adaptive.min_spp = int(min_n->integer_in(kSppRange));
    if (max_n) s.adaptive.max_spp = int(max_n->integer_in(kSppRange));
    if (s.adaptive.max_spp < s.adaptive.min_spp) {
      std::string bound = "must be >= min_spp (" + std::to_string(s.adaptive.min_spp) + ")";
      if (max_n) max_n->fail_got(bound);
      min_n->fail_got("must be <= max_spp (default " + std::to_string(s.adaptive.max_spp) + ")");
    }
    if (auto t = a.get("threshold")) s.adaptive.threshold = t->positive();
    if (auto m = a.get("metric")) s.adaptive.metric = m->choice(kAdaptiveMetricNames);
    if (auto v = a.get("variance")) s.adaptive.variance = v->choice(kAdaptiveVarianceNames);
    if (auto d = a.get("decision")) {
      s.adaptive.decision = d->choice(kAdaptiveDecisionNames);
      if (std::string p = decision_problem(s.adaptive, scene_.film.filter.reconstruction); !p.empty()) d->fail(p);
    }
  }
}

void SceneParser::integrator(const JsonObject& o) {
  o.allow({"max_depth", "rr_depth", "regularize", "environment_sampling"});
  if (auto n = o.get("max_depth")) scene_.integrator.max_depth = n->int_at_least(1);
  if (auto n = o.get("rr_depth")) scene_.integrator.rr_depth = n->int_at_least(1);
  if (auto n = o.get("regularize")) scene_.integrator.regularize = n->boolean();
  if (auto n = o.get("environment_sampling"))
    scene_.integrator.environment_sampling = n->choice(kEnvironmentSamplingNames);
}

int SceneParser::texture_named(const JsonNode& n) const {
  std::string name = n.string();
  auto it = texture_index_.find(name);
  if (it == texture_index_.end()) {
    std::string known;
    for (const auto& [k, v] : texture_index_) known += std::string(known.empty() ? "" : ", ") + json_quoted(k);
    n.fail("unknown texture " + json_quoted(name) +
           (known.empty() ? " (the scene has no \"textures\")" : " (textures: " + known + ")"));
  }
  return it->second;
}

// A checkerboard's colour: a number (grey), [r, g, b] in [0, 1], or a texture's name.
TextureInput SceneParser::texture_input(const JsonNode& n, int from) {
  TextureInput in;
  if (n.value().is_string()) {
    in.texture = texture_named(n);
    texture_refs_[size_t(from)].push_back({in.texture, n});
  } else if (n.value().is_number()) {
    in.value = Vec3(n.in_unit_interval());
  } else {
    in.value = n.color();
  }
  return in;
}

TextureInput SceneParser::texture_input_non_negative(const JsonNode& n, int from) {
  if (n.value().is_string()) return texture_input(n, from);
  TextureInput in;
  in.value = n.value().is_number() ? Vec3(n.non_negative()) : n.radiance();
  return in;
}

void SceneParser::textures(const JsonNode& n) {
  JsonObject all = n.object();
  // Names first: a texture may use one defined after it.
  for (auto it = n.value().begin(); it != n.value().end(); ++it) {
    if (it.key().empty()) all.child(it.key()).fail_key("texture name must not be empty");
    texture_index_[it.key()] = int(texture_index_.size());
  }
  texture_refs_.resize(texture_index_.size());
  for (auto it = n.value().begin(); it != n.value().end(); ++it) {
    JsonNode tn = all.child(it.key());
    JsonObject o = tn.object();
    TextureDesc t;
    t.name = it.key();
    t.where = tn.where();
    const int self = int(scene_.textures.size());
    auto uv_scale = [&](const JsonNode& sn) {
      if (sn.value().is_number()) {
        t.scale_u = t.scale_v = sn.positive();
      } else {
        if (!sn.value().is_array() || sn.value().size() != 2) sn.fail_got("must be a number or [su, sv]");
        t.scale_u = sn.at(0).positive(), t.scale_v = sn.at(1).positive();
      }
    };
    std::string type =
        o.require("type").choice({"constant", "checkerboard", "image", "scale", "mix", "invert", "power"});
    if (type == "scale") {
      o.allow({"type", "tex", "scale"});
      t.kind = TextureDesc::Kind::Scale;
      t.tex = texture_input_non_negative(o.require("tex"), self);
      if (auto x = o.get("scale")) t.scale = texture_input_non_negative(*x, self);
    } else if (type == "mix") {
      o.allow({"type", "tex1", "tex2", "amount"});
      t.kind = TextureDesc::Kind::Mix;
      if (auto x = o.get("tex1")) t.tex1 = texture_input_non_negative(*x, self);
      if (auto x = o.get("tex2")) t.tex2 = texture_input_non_negative(*x, self);
      if (auto x = o.get("amount")) {
        if (x->value().is_string()) {
          t.amount = texture_input(*x, self);
        } else {
          t.amount.value = Vec3(x->in_unit_interval());
        }
      }
    } else if (type == "invert" || type == "power") {
      o.allow(type == "invert" ? std::initializer_list<const char*>{"type", "tex"}
                               : std::initializer_list<const char*>{"type", "tex", "exponent"});
      t.kind = type == "invert" ? TextureDesc::Kind::Invert : TextureDesc::Kind::Power;
      t.tex = texture_input_non_negative(o.require("tex"), self);
      if (type == "power") t.exponent = o.require("exponent").positive();
    } else if (type == "constant") {
      o.allow({"type", "value"});
      t.kind = TextureDesc::Kind::Constant;
      JsonNode v = o.require("value");
      t.value = v.value().is_number() ? Vec3(v.in_unit_interval()) : v.color();
    } else if (type == "checkerboard") {
      o.allow({"type", "scale", "color0", "color1"});
      t.kind = TextureDesc::Kind::Checkerboard;
      if (auto x = o.get("scale")) uv_scale(*x);
      t.color0 = texture_input(o.require("color0"), self);
      t.color1 = texture_input(o.require("color1"), self);
    } else {
      o.allow({"type", "file", "filter", "wrap", "encoding", "scale"});
      t.kind = TextureDesc::Kind::Image;
      JsonNode file = o.require("file");
      t.file = dir_ / file.string();
      t.where = file.where();
      std::string reason;
      if (!can_open_file(t.file, reason)) file.fail("cannot open " + json_quoted(file.string()) + ": " + reason);
      if (auto x = o.get("filter")) {
        static const std::map<std::string, TextureFilter> k = {{"none", TextureFilter::None},
                                                               {"bilinear", TextureFilter::Bilinear},
                                                               {"trilinear", TextureFilter::Trilinear},
                                                               {"ewa", TextureFilter::Ewa},
                                                               {"anisotropic", TextureFilter::Ewa}};
        t.filter = k.at(x->choice({"none", "bilinear", "trilinear", "ewa", "anisotropic"}));
      }
      if (auto x = o.get("wrap")) {
        static const std::map<std::string, TextureWrap> k = {{"repeat", TextureWrap::Repeat},
                                                             {"clamp", TextureWrap::Clamp},
                                                             {"black", TextureWrap::Black},
                                                             {"mirror", TextureWrap::Mirror}};
        t.wrap = k.at(x->choice({"repeat", "clamp", "black", "mirror"}));
      }
      if (auto x = o.get("encoding")) {
        std::string e = x->choice({"auto", "srgb", "linear"});
        t.encoding = e == "srgb"     ? TextureEncoding::Srgb
                     : e == "linear" ? TextureEncoding::Linear
                                     : TextureEncoding::Auto;
      }
      if (auto x = o.get("scale")) uv_scale(*x);
    }
    scene_.textures.push_back(std::move(t));
  }
  // No cycles (a checkerboard of itself would recurse forever while rendering). Iterative
  // depth-first search: a chain of many textures must not overflow the stack here either.
  std::vector<int> state(scene_.textures.size(), 0);  // 0 new, 1 on the path, 2 done
  std::vector<int> order;                             // finished: every input before its users
  for (size_t root = 0; root < state.size(); ++root) {
    if (state[root]) continue;
    std::vector<std::pair<int, size_t>> stack{{int(root), 0}};  // (texture, next edge)
    state[root] = 1;
    while (!stack.empty()) {
      auto& [t, e] = stack.back();
      const auto& refs = texture_refs_[size_t(t)];
      if (e == refs.size()) {
        state[size_t(t)] = 2;
        order.push_back(t);
        stack.pop_back();
        continue;
      }
      const auto& [to, where] = refs[e++];
      if (state[size_t(to)] == 1) {
        std::string path;
        for (const auto& [k, i] : stack) path += json_quoted(scene_.textures[size_t(k)].name) + " -> ";
        where.fail("makes a cycle of textures: " + path + json_quoted(scene_.textures[size_t(to)].name));
      }
      if (state[size_t(to)] == 0) state[size_t(to)] = 1, stack.push_back({to, 0});
    }
  }
  // Bounded work per lookup (kMaxTextureEvaluation), computed inputs first: in the order the
  // search above finished the textures.
  const std::vector<long long> cost = texture_evaluation_cost(scene_.textures, order);
  for (size_t i = 0; i < cost.size(); ++i)
    if (cost[i] > kMaxTextureEvaluation)
      all.child(scene_.textures[i].name)
          .fail("evaluates " + (cost[i] >= (1LL << 40) ? std::string("more than 2^40") : std::to_string(cost[i])) +
                " scale/mix/invert/power nodes per lookup (at most " + std::to_string(kMaxTextureEvaluation) + ")");
}

void SceneParser::textured_color(const JsonNode& n, Material& m, MaterialParam p, Vec3& field) const {
  if (n.value().is_string()) {
    m.textures.push_back({p, texture_named(n)});
  } else {
    field = n.color();
  }
}

void SceneParser::textured_unit(const JsonNode& n, Material& m, MaterialParam p, float& field) const {
  if (n.value().is_string()) {
    m.textures.push_back({p, texture_named(n)});
  } else {
    field = n.in_unit_interval();
  }
}

void SceneParser::materials(const JsonNode& n) {
  JsonObject all = n.object();
  std::vector<std::pair<int, JsonNode>> mixes;  // (material, its "materials" array), resolved after all names
  for (auto it = n.value().begin(); it != n.value().end(); ++it) {
    JsonNode mn = all.child(it.key());
    if (it.key().empty()) mn.fail_key("material name must not be empty");
    JsonObject o = mn.object();
    Material m;
    m.name = it.key();
    std::string type = o.require("type").choice({"diffuse", "glossy", "mirror", "dielectric", "emitter", "conductor",
                                                 "coated_diffuse", "coated_conductor", "thin_dielectric", "mix"});
    if (type == "diffuse") {
      o.allow({"type", "albedo"});
      m.type = MaterialType::Diffuse;
      m.albedo = Vec3(0.8f);
    } else if (type == "glossy") {
      o.allow({"type", "albedo", "roughness", "exponent", "lobe", "energy_compensation"});
      m.type = MaterialType::Glossy;
      m.albedo = Vec3(0.9f);
      auto rough = o.get("roughness"), expo = o.get("exponent"), lobe = o.get("lobe");
      if (rough && expo)
        expo->fail_key("cannot be combined with roughness: give roughness (GGX lobe) or exponent (Phong lobe)");
      if (lobe) {
        bool phong = lobe->choice({"ggx", "phong"}) == "phong";
        if (phong && rough) lobe->fail_got("does not match roughness (a GGX parameter)");
        if (!phong && expo) lobe->fail_got("does not match exponent (a Phong parameter)");
        if (!rough && !expo) o.require(phong ? "exponent" : "roughness");
      }
      if (!rough && !expo) mn.fail("needs roughness (GGX lobe) or exponent (Phong lobe)");
      if (rough) {
        m.lobe = GlossLobe::GGX;
        textured_unit(*rough, m, MaterialParam::Roughness, m.roughness);
      } else {
        m.lobe = GlossLobe::Phong;
        m.exponent = expo->positive();
      }
      if (auto x = o.get("energy_compensation")) {
        m.energy_compensation = x->boolean();
        if (m.lobe == GlossLobe::Phong)
          x->fail_key("applies to the GGX lobe (roughness) only, not to exponent (Phong)");
      }
    } else if (type == "mirror") {
      o.allow({"type", "albedo"});
      m.type = MaterialType::Mirror;
      m.albedo = Vec3(1.0f);
    } else if (type == "dielectric") {
      o.allow({"type", "albedo", "ior", "roughness", "energy_compensation"});
      m.type = MaterialType::Dielectric;
      m.albedo = Vec3(1.0f);
      if (auto x = o.get("ior")) m.ior = x->positive();
      if (auto x = o.get("roughness")) textured_unit(*x, m, MaterialParam::Roughness, m.roughness);
      if (auto x = o.get("energy_compensation")) m.energy_compensation = x->boolean();
    } else if (type == "thin_dielectric") {
      o.allow({"type", "albedo", "ior"});
      m.type = MaterialType::ThinDielectric;
      m.albedo = Vec3(1.0f);
      if (auto x = o.get("ior")) m.ior = x->positive();
    } else if (type == "mix") {
      o.allow({"type", "materials", "amount"});
      m.type = MaterialType::Mix;
      JsonNode names = o.require("materials");
      if (!names.value().is_array() || names.value().size() != 2)
        names.fail_got("must be [\"first\", \"second\"] (two material names)");
      names.at(0).string(), names.at(1).string();
      mixes.push_back({int(scene_.materials.size()), names});
      if (auto x = o.get("amount")) textured_unit(*x, m, MaterialParam::Amount, m.amount);
    } else if (type == "conductor") {
      o.allow({"type", "eta", "k", "metal", "reflectance", "roughness", "energy_compensation"});
      m.type = MaterialType::Conductor;
      m.albedo = Vec3(1.0f);
      conductor_index(mn, o, m);
      if (auto x = o.get("roughness")) textured_unit(*x, m, MaterialParam::Roughness, m.roughness);
      if (auto x = o.get("energy_compensation")) m.energy_compensation = x->boolean();
    } else if (type == "coated_diffuse") {
      m.type = MaterialType::CoatedDiffuse;
      m.albedo = Vec3(0.5f);
      auto model = o.get("model");
      m.layered = model && model->choice({"analytic", "layered"}) == "layered";
      if (m.layered) {
        o.allow(
            {"type", "model", "albedo", "roughness", "ior", "thickness", "medium_albedo", "g", "max_depth", "samples"});
        coat_layers(o, m);
      } else {
        o.allow({"type", "model", "albedo", "roughness", "ior", "coat_color", "coat_thickness"});
        if (auto x = o.get("ior")) {
          // The coat's albedo tables hold indices 1 to 3 (ggx_albedo_tables.h); 1 is no coat.
          m.ior = x->number();
          if (!(m.ior >= 1 && m.ior <= 3)) x->fail_got("must be in [1,3] (the coat's index relative to the outside)");
        }
        if (auto x = o.get("coat_color")) textured_color(*x, m, MaterialParam::CoatColor, m.coat_color);
        if (auto x = o.get("coat_thickness")) m.coat_thickness = x->non_negative();
      }
      if (auto x = o.get("roughness")) textured_unit(*x, m, MaterialParam::Roughness, m.roughness);
    } else if (type == "coated_conductor") {
      o.allow({"type", "roughness", "ior", "eta", "k", "metal", "reflectance", "base_roughness", "thickness",
               "medium_albedo", "g", "max_depth", "samples"});
      m.type = MaterialType::CoatedConductor;
      m.albedo = Vec3(1.0f);
      m.layered = true;
      conductor_index(mn, o, m);
      coat_layers(o, m);
      if (auto x = o.get("roughness")) textured_unit(*x, m, MaterialParam::Roughness, m.roughness);
      if (auto x = o.get("base_roughness")) textured_unit(*x, m, MaterialParam::BaseRoughness, m.base_roughness);
    } else {
      o.allow({"type", "radiance", "two_sided", "scale"});
      m.type = MaterialType::Emitter;
      JsonNode r = o.require("radiance");
      if (r.value().is_string()) {
        // A textured emitter: radiance = texel x scale (texture_set.h, emission()).
        m.textures.push_back({MaterialParam::Radiance, texture_named(r)});
        m.radiance = Vec3(1.0f);
      } else {
        m.radiance = r.radiance();
      }
      if (auto x = o.get("scale")) {
        const Vec3 k = x->value().is_number() ? Vec3(float(x->non_negative())) : x->radiance();
        m.radiance = Vec3(m.radiance.x * k.x, m.radiance.y * k.y, m.radiance.z * k.z);
      }
      if (auto x = o.get("two_sided")) m.two_sided = x->boolean();
    }
    if (auto a = o.get("albedo")) textured_color(*a, m, MaterialParam::Albedo, m.albedo);
    material_index_[m.name] = int(scene_.materials.size());
    scene_.materials.push_back(std::move(m));
  }
  mix_materials(mixes);
}

// A conductor's complex index: a named metal, eta and k, or pbrt-v4's normal-incidence
// reflectance (conductor and coated_conductor; relative to the outside, the coat divides it).
void SceneParser::conductor_index(const JsonNode& mn, const JsonObject& o, Material& m) const {
  auto metal = o.get("metal"), eta = o.get("eta"), k = o.get("k"), refl = o.get("reflectance");
  if (metal && (eta || k)) (eta ? eta : k)->fail_key("cannot be combined with metal: give metal or eta and k");
  if (refl && (metal || eta || k)) refl->fail_key("cannot be combined with metal, eta or k: give one of them");
  if (refl) {
    // pbrt-v4's conductor by reflectance: eta = 1, k from the normal-incidence reflectance.
    Vec3 r{0.0f};
    textured_color(*refl, m, MaterialParam::Reflectance, r);
    conductor_from_reflectance(r, &m);
  } else if (metal) {
    const NamedMetal* nm = find_named_metal(metal->string());
    if (!nm) metal->fail_got("must be one of " + named_metal_list());
    m.eta = nm->eta, m.k = nm->k;
  } else {
    if (!eta && !k) mn.fail("needs metal (one of " + named_metal_list() + ") or eta and k");
    JsonNode e = eta ? *eta : o.require("eta"), kk = k ? *k : o.require("k");
    m.eta = e.vec3();
    m.k = kk.vec3();
    for (int c = 0; c < 3; ++c)
      if (!(std::isfinite(m.eta[c]) && m.eta[c] > 0)) e.fail_got("must have finite components > 0");
    for (int c = 0; c < 3; ++c)
      if (!(std::isfinite(m.k[c]) && m.k[c] >= 0)) kk.fail_got("must have finite components >= 0");
  }
}

// The slab of a layered coat (render/bxdf/layered.h), pbrt-v4's parameters: any index > 0.
void SceneParser::coat_layers(const JsonObject& o, Material& m) const {
  if (auto x = o.get("ior")) m.ior = x->positive();
  if (auto x = o.get("thickness")) m.layers.thickness = x->non_negative();
  if (auto x = o.get("medium_albedo")) m.layers.albedo = x->color();
  if (auto x = o.get("g")) {
    m.layers.g = x->number();
    if (!(m.layers.g >= -1 && m.layers.g <= 1)) x->fail_got("must be in [-1,1]");
  }
  if (auto x = o.get("max_depth")) m.layers.max_depth = int(x->integer(0, kMaxLayerDepth));
  if (auto x = o.get("samples")) m.layers.samples = int(x->integer(1, kMaxLayerSamples));
}

// A mix's two materials, by name (any material of the file, before or after it): none an
// emitter (a mix chooses how a surface scatters; lights are whole materials), and no mix
// reaching itself through others (resolving it would never end).
void SceneParser::mix_materials(const std::vector<std::pair<int, JsonNode>>& mixes) {
  for (const auto& [index, names] : mixes) {
    Material& m = scene_.materials[size_t(index)];
    for (size_t i = 0; i < 2; ++i) {
      const JsonNode n = names.at(i);
      const int c = material_named(n);
      if (scene_.materials[size_t(c)].type == MaterialType::Emitter)
        n.fail("names the emitter " + json_quoted(n.string()) + ": a mix's materials must not emit");
      m.mix[i] = c;
    }
  }
  // Every mix reaches only finitely many mixes: follow the first-found unvisited edges.
  std::vector<int> state(scene_.materials.size(), 0);  // 0 new, 1 on the path, 2 done
  std::map<int, JsonNode> where;
  for (const auto& [index, names] : mixes) where.emplace(index, names);
  for (const auto& [root, root_names] : mixes) {
    if (state[size_t(root)]) continue;
    std::vector<std::pair<int, int>> stack{{root, 0}};  // (mix, next component)
    state[size_t(root)] = 1;
    while (!stack.empty()) {
      auto& [mi, e] = stack.back();
      if (e == 2) {
        state[size_t(mi)] = 2;
        stack.pop_back();
        continue;
      }
      const int to = scene_.materials[size_t(mi)].mix[e];
      const JsonNode at = where.at(mi).at(size_t(e++));
      if (scene_.materials[size_t(to)].type != MaterialType::Mix) continue;
      if (state[size_t(to)] == 1) {
        std::string path;
        for (const auto& [k, unused] : stack) path += json_quoted(scene_.materials[size_t(k)].name) + " -> ";
        at.fail("makes a cycle of mix materials: " + path + json_quoted(scene_.materials[size_t(to)].name));
      }
      if (state[size_t(to)] == 0) state[size_t(to)] = 1, stack.push_back({to, 0});
    }
  }
}

int SceneParser::material_named(const JsonNode& n) const {
  std::string name = n.string();
  auto it = material_index_.find(name);
  if (it == material_index_.end()) n.fail("unknown material " + json_quoted(name));
  return it->second;
}

Vec3 SceneParser::scale(const JsonNode& n) const {
  if (n.value().is_number()) {
    float s = n.number();
    if (s == 0) n.fail_got("must be non-zero");
    return Vec3(s);
  }
  Vec3 s = n.vec3();
  if (s.x == 0 || s.y == 0 || s.z == 0) n.fail_got("must have non-zero components");
  return s;
}

Affine SceneParser::rotation(const JsonNode& n) const {
  JsonObject o = n.object();
  o.allow({"axis", "degrees"});
  Vec3 axis = o.require("axis").nonzero_vec3();
  return Affine::rotate(axis, o.require("degrees").number());
}

Affine SceneParser::transform(const JsonNode& n) const {
  JsonObject o = n.object();
  o.allow({"translate", "rotate", "scale", "matrix"});
  Affine m;
  if (auto mat = o.get("matrix")) {
    for (const char* other : {"translate", "rotate", "scale"})
      if (o.has(other)) mat->fail_key(std::string("cannot be combined with ") + other);
    const json& v = mat->value();
    if (!v.is_array() || (v.size() != 12 && v.size() != 16)) mat->fail_got("must be an array of 12 or 16 numbers");
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) m.m[r][c] = mat->at(size_t(4 * r + c)).number();
    if (v.size() == 16)
      for (int c = 0; c < 4; ++c)
        if (mat->at(size_t(12 + c)).number() != (c == 3 ? 1.0f : 0.0f)) mat->fail("last row must be 0 0 0 1");
  } else {
    Affine r;
    if (auto rot = o.get("rotate")) {
      if (rot->value().is_array()) {
        size_t count = rot->array_size(1);
        for (size_t i = 0; i < count; ++i) r = rotation(rot->at(i)) * r;  // first listed = innermost
      } else {
        r = rotation(*rot);
      }
    }
    Affine t, s;
    if (auto x = o.get("translate")) t = Affine::translate(x->vec3());
    if (auto x = o.get("scale")) s = Affine::scale(scale(*x));
    m = t * r * s;
  }
  float det = m.determinant();
  if (!(std::isfinite(det) && det != 0)) n.fail("is singular (determinant " + std::to_string(det) + ")");
  return m;
}

std::vector<MotionKey> SceneParser::motion(const JsonNode& n, bool sphere) const {
  std::vector<MotionKey> keys;
  size_t count = n.array_size(2);
  for (size_t i = 0; i < count; ++i) {
    JsonObject o = n.at(i).object();
    o.allow({"time", "translate", "rotate", "scale"});
    MotionKey k;
    JsonNode t = o.require("time");
    check_time(t, i ? keys.back().time : 0, i == 0);
    k.time = t.number();
    if (auto x = o.get("translate")) k.translate = x->vec3();
    if (auto x = o.get("rotate")) {
      JsonObject r = x->object();
      r.allow({"axis", "degrees"});
      Vec3 axis = r.require("axis").nonzero_vec3();
      k.rotate = Quat::from_axis_angle(axis, r.require("degrees").number());
    }
    if (auto x = o.get("scale")) {
      k.scale = scale(*x);
      if (sphere && !(k.scale.x == k.scale.y && k.scale.y == k.scale.z))
        x->fail_got("must be uniform for a sphere (one number); use a mesh for an ellipsoid");
    }
    keys.push_back(k);
  }
  return keys;
}

void SceneParser::place(ShapeDesc& s, const JsonObject& o, const std::string& where) const {
  if (auto t = o.get("transform")) s.transform = transform(*t);
  if (auto m = o.get("motion")) s.motion = motion(*m, s.kind == ShapeDesc::Kind::Sphere);
  s.where = doc_.name() + ": " + where;
}

MeshData SceneParser::quad(const JsonObject& o) {
  Vec3 corner = o.require("corner").vec3();
  JsonNode e1n = o.require("edge1"), e2n = o.require("edge2");
  Vec3 e1 = e1n.nonzero_vec3(), e2 = e2n.nonzero_vec3();
  if (is_black(cross(e1, e2))) e2n.fail_got("must not be parallel to edge1");
  MeshData m;
  m.positions = {corner, corner + e1, corner + e1 + e2, corner + e2};
  m.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise about cross(edge1, edge2)
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  keep_triangles(m, e2n);
  return m;
}

// Drops degenerate triangles (repeated vertex, zero area) and counts them.
void SceneParser::keep_triangles(MeshData& mesh, const JsonNode& where) {
  size_t kept = 0, skipped = 0;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const auto& p = mesh.positions;
    if (a == b || b == c || a == c || is_black(cross(p[b] - p[a], p[c] - p[a]))) {
      ++skipped;
      continue;
    }
    mesh.indices[kept++] = a, mesh.indices[kept++] = b, mesh.indices[kept++] = c;
  }
  mesh.indices.resize(kept);
  scene_.degenerate_triangles += int64_t(skipped);
  if (kept == 0) where.fail("leaves no triangles (all " + std::to_string(skipped) + " are degenerate)");
}

void SceneParser::objects(const JsonNode& n, int prototype) {
  size_t count = n.array_size(prototype >= 0 ? 1 : 0);
  std::vector<ShapeDesc>& out = prototype >= 0 ? scene_.prototypes[size_t(prototype)].shapes : scene_.shapes;
  for (size_t i = 0; i < count; ++i) {
    JsonNode on = n.at(i);
    JsonObject o = on.object();
    JsonNode type_node = o.require("type");
    std::string type = type_node.choice({"sphere", "quad", "mesh", "obj", "instance"});
    if (type == "instance") {
      // pbrt-v4 does not nest instances either; Embree would need two instance levels.
      if (prototype >= 0) type_node.fail_got("is not allowed inside a prototype (instances do not nest)");
      instance(on, o);
      continue;
    }
    if (prototype >= 0)
      if (auto m = o.get("motion")) m->fail_key("is not allowed inside a prototype (give the instance a motion)");
    ShapeDesc s;
    if (type == "sphere") {
      o.allow({"type", "material", "transform", "motion", "center", "radius"});
      s.kind = ShapeDesc::Kind::Sphere;
      if (auto c = o.get("center")) s.center = c->vec3();
      s.radius = o.require("radius").positive();
    } else if (type == "quad") {
      o.allow({"type", "material", "transform", "motion", "corner", "edge1", "edge2"});
      s.mesh = quad(o);
    } else if (type == "mesh") {
      o.allow({"type", "material", "transform", "motion", "vertices", "indices", "normals", "uvs"});
      JsonNode vn = o.require("vertices");
      size_t nv = vn.array_size(1);
      if (nv > UINT32_MAX) vn.fail("has too many vertices");
      s.mesh.positions.reserve(nv);
      for (size_t v = 0; v < nv; ++v) s.mesh.positions.push_back(vn.at(v).vec3());
      JsonNode in = o.require("indices");
      size_t ni = in.array_size(3);
      if (ni % 3) in.fail("length must be a multiple of 3, got " + std::to_string(ni));
      s.mesh.indices.reserve(ni);
      for (size_t k = 0; k < ni; ++k) {
        const json& x = in.value()[k];  // fast path; build the element's node only to report
        if (!x.is_number_unsigned() || x.get<uint64_t>() >= nv)
          in.at(k).fail_got("must be a vertex index in [0, " + std::to_string(nv - 1) + "]");
        s.mesh.indices.push_back(uint32_t(x.get<uint64_t>()));
      }
      if (auto nn = o.get("normals")) {
        if (nn->array_size(0) != nv)
          nn->fail("must have one normal per vertex (" + std::to_string(nv) + "), got " +
                   std::to_string(nn->value().size()));
        for (size_t v = 0; v < nv; ++v) s.mesh.normals.push_back(nn->at(v).nonzero_vec3());
      }
      if (auto un = o.get("uvs")) {
        if (un->array_size(0) != nv)
          un->fail("must have one [u, v] per vertex (" + std::to_string(nv) + "), got " +
                   std::to_string(un->value().size()));
        s.mesh.uvs.reserve(nv);
        for (size_t v = 0; v < nv; ++v) {
          JsonNode e = un->at(v);
          if (!e.value().is_array() || e.value().size() != 2) e.fail_got("must be [u, v]");
          s.mesh.uvs.push_back({e.at(0).number(), e.at(1).number()});
        }
      }
      keep_triangles(s.mesh, in);
    } else {
      o.allow({"type", "material", "transform", "motion", "file"});
      JsonNode file = o.require("file");
      fs::path path = dir_ / file.string();
      std::string reason;
      if (!can_open_file(path, reason)) file.fail("cannot open " + json_quoted(file.string()) + ": " + reason);
      int material = -1;
      if (auto m = o.get("material")) material = material_named(*m);
      if (auto m = o.get("material")) refuse_emitter(*m, material, prototype);
      place(s, o, on.path());
      pending_.push_back({out.size(), path, file, material, std::move(s), prototype});
      continue;
    }
    JsonNode mn = o.require("material");
    s.material = material_named(mn);
    refuse_emitter(mn, s.material, prototype);
    place(s, o, on.path());
    out.push_back(std::move(s));
  }
}

// pbrt-v4 refuses area lights in instances: the light set holds each emitter once, in
// world space, and an instanced emitter would be many.
void SceneParser::refuse_emitter(const JsonNode& at, int material, int prototype) const {
  if (prototype < 0 || material < 0 || scene_.materials[size_t(material)].type != MaterialType::Emitter) return;
  at.fail_got("is an emitter; emitters cannot be inside a prototype (instanced area lights are not supported)");
}

// "prototypes": {"name": [object, ...], ...}: named shape groups, placed by "instance" objects.
void SceneParser::prototypes(const JsonNode& n) {
  JsonObject all = n.object();
  for (auto it = n.value().begin(); it != n.value().end(); ++it) {
    JsonNode pn = all.child(it.key());
    if (it.key().empty()) pn.fail_key("prototype name must not be empty");
    if (!pn.value().is_array()) pn.fail_got("must be an array of objects");
    if (pn.value().empty()) pn.fail("must hold at least one object");
    prototype_index_[it.key()] = int(scene_.prototypes.size());
    PrototypeDesc p;
    p.name = it.key();
    p.where = doc_.name() + ": " + pn.path();
    scene_.prototypes.push_back(std::move(p));
    objects(pn, int(scene_.prototypes.size()) - 1);
  }
}

// {"type": "instance", "prototype": name, "transform": ..., "motion": [...]}
void SceneParser::instance(const JsonNode& on, const JsonObject& o) {
  o.allow({"type", "prototype", "transform", "motion"});
  JsonNode pn = o.require("prototype");
  const std::string name = pn.string();
  auto it = prototype_index_.find(name);
  if (it == prototype_index_.end()) {
    std::string known;
    for (const auto& [k, v] : prototype_index_) known += (known.empty() ? "" : ", ") + json_quoted(k);
    pn.fail_got("is not a prototype (" +
                (known.empty() ? std::string("the scene has no \"prototypes\"") : "prototypes: " + known) + ")");
  }
  InstanceDesc d;
  d.prototype = it->second;
  if (auto t = o.get("transform")) d.transform = transform(*t);
  if (auto m = o.get("motion")) d.motion = motion(*m, false);
  d.where = doc_.name() + ": " + on.path();
  scene_.instances.push_back(std::move(d));
}

void SceneParser::lights(const JsonNode& n) {
  size_t count = n.array_size(0);
  std::optional<JsonNode> environment;
  for (size_t i = 0; i < count; ++i) {
    JsonNode ln = n.at(i);
    JsonObject o = ln.object();
    std::string type = o.require("type").choice({"quad", "sphere", "environment", "point", "spot", "distant"});
    if (type == "point" || type == "spot" || type == "distant") {
      delta_light(ln, o, type);
      continue;
    }
    if (type == "environment") {
      o.allow({"type", "radiance", "file", "scale", "rotation_deg"});
      if (environment) ln.fail("is a second environment light (at most one; the first is " + environment->path() + ")");
      environment = ln;
      environment_light(ln, o);
      continue;
    }
    ShapeDesc s;
    Material m;
    m.name = ln.path();
    m.type = MaterialType::Emitter;
    if (type == "quad") {
      o.allow({"type", "corner", "edge1", "edge2", "radiance", "two_sided", "transform", "motion"});
      s.mesh = quad(o);
      if (auto t = o.get("two_sided")) m.two_sided = t->boolean();
    } else {
      o.allow({"type", "center", "radius", "radiance", "transform", "motion"});
      s.kind = ShapeDesc::Kind::Sphere;
      if (auto c = o.get("center")) s.center = c->vec3();
      s.radius = o.require("radius").positive();
    }
    m.radiance = o.require("radiance").radiance();
    s.material = int(scene_.materials.size());
    scene_.materials.push_back(m);
    place(s, o, ln.path());
    scene_.shapes.push_back(std::move(s));
  }
}

// A constant environment (`radiance`) or an equirectangular image (`file`, with `scale` and
// `rotation_deg`), read and checked here so that a bad image stops the load, not the render.
void SceneParser::environment_light(const JsonNode& ln, const JsonObject& o) {
  EnvironmentDesc& e = scene_.environment;
  auto radiance = o.get("radiance"), file = o.get("file");
  if (radiance && file) file->fail_key("cannot be combined with radiance: give radiance (constant) or file (an image)");
  if (!radiance && !file) ln.fail("needs radiance (a constant environment) or file (an equirectangular image)");
  if (radiance) {
    for (const char* k : {"scale", "rotation_deg"})
      if (auto x = o.get(k)) x->fail_key("applies to an image (file) only; scale the radiance instead");
    e.radiance = radiance->radiance();
    return;
  }
  if (auto x = o.get("scale")) e.scale = x->value().is_number() ? Vec3(x->non_negative()) : x->radiance();
  if (auto x = o.get("rotation_deg")) e.rotation_deg = x->number();
  const std::string name = file->string();
  if (name.empty()) file->fail_got("must name an image file");
  std::optional<fs::path> path = find_scene_asset(dir_, name);
  if (!path) {
    const fs::path assets = generated_asset_dir();
    file->fail("cannot open " + json_quoted(name) + ": no such file in the scene's directory" +
               (assets.empty() || fs::path(name).is_absolute()
                    ? std::string()
                    : " or the generated assets " + json_quoted(assets.string())));
  }
  EnvironmentImage image;
  std::string reason;
  if (!read_environment_image(*path, &image, &reason))
    file->fail("cannot read " + json_quoted(name) + ": " + printable(reason));
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const float v = image.rgb[i];
    if (std::isfinite(v) && v >= 0) continue;
    const std::size_t t = i / 3;
    std::ostringstream m;
    m << json_quoted(name) << " has " << (std::isfinite(v) ? "a negative value " : "a non-finite value ") << v
      << " at texel (" << t % std::size_t(image.width) << ", " << t / std::size_t(image.width) << ") channel " << i % 3
      << ": an environment image must be finite and >= 0";
    file->fail(m.str());
  }
  e.file = path->string();
  e.width = image.width, e.height = image.height;
  e.rgb = std::move(image.rgb);
}

// v / |v|, refused at `at` when |v| is 0 or not finite in float (a direction written as
// [1e-30, 0, 0] or [1e30, 1e30, 0] is non-zero yet cannot be normalised).
Vec3 unit_direction(const JsonNode& at, const Vec3& v, const std::string& what) {
  const float len = length(v);
  if (!(len > 0 && std::isfinite(len))) at.fail_got(what + " cannot be normalised in float (length 0 or overflowing)");
  return v / len;
}

float cos_deg(float degrees) { return float(std::cos(double(degrees) * M_PI / 180)); }

// Point, spot and distant lights (SceneDesc::delta_lights).
void SceneParser::delta_light(const JsonNode& ln, const JsonObject& o, const std::string& type) {
  DeltaLightDesc l;
  if (type == "distant") {
    o.allow({"type", "direction", "irradiance"});
    l.kind = DeltaLightDesc::Kind::Distant;
    JsonNode d = o.require("direction");
    l.direction = unit_direction(d, d.nonzero_vec3(), "is a direction that");
    l.irradiance = o.require("irradiance").radiance();
    scene_.delta_lights.push_back(l);
    return;
  }
  std::optional<JsonNode> at_position = o.get("position");
  if (type == "point") {
    o.allow({"type", "position", "intensity", "transform", "motion"});
  } else {
    o.allow({"type", "position", "direction", "look_at", "intensity", "cone_angle_deg", "falloff_start_deg",
             "transform", "motion"});
    l.kind = DeltaLightDesc::Kind::Spot;
  }
  if (at_position) l.position = at_position->vec3();
  l.intensity = o.require("intensity").radiance();
  if (l.kind == DeltaLightDesc::Kind::Spot) {
    auto dir = o.get("direction"), look = o.get("look_at");
    if (dir && look) look->fail_key("cannot be combined with direction (give one of them)");
    if (dir) {
      l.direction = unit_direction(*dir, dir->nonzero_vec3(), "is a direction that");
    } else if (look) {
      const Vec3 d = look->vec3() - l.position;
      if (is_black(d)) look->fail_got("must differ from the position");
      l.direction = unit_direction(*look, d, "minus the position");
    } else {
      ln.fail("needs \"direction\" or \"look_at\" (the axis of a spot light)");
    }
    float cone = 30, start;
    if (auto c = o.get("cone_angle_deg")) {
      cone = c->number();
      if (!(cone > 0 && cone <= 180)) c->fail_got("must be in (0, 180] (degrees from the axis to the cone's edge)");
    }
    start = std::max(0.0f, cone - 5);
    if (auto f = o.get("falloff_start_deg")) {
      start = f->number();
      if (!(start >= 0 && start <= cone)) {
        std::ostringstream m;
        m << "must be in [0, cone_angle_deg] = [0, " << cone << "]";
        f->fail_got(m.str());
      }
    }
    l.cos_cone = cos_deg(cone);
    l.cos_falloff_start = std::max(cos_deg(start), l.cos_cone);
  }
  std::optional<JsonNode> at_transform = o.get("transform"), at_motion = o.get("motion");
  if (at_transform) l.transform = transform(*at_transform);
  if (at_motion) l.motion = motion(*at_motion, false);
  // The light's world position and axis at its static transform and at every key must be
  // finite (and the axis normalisable), so nothing downstream divides by zero or infinity.
  auto check_world = [&](const Affine& m, const JsonNode& at) {
    if (!is_finite(m.point(l.position))) at.fail("puts the light at a position beyond float range");
    if (l.kind == DeltaLightDesc::Kind::Spot) {
      const float len = length(m.vector(l.direction));
      if (!(len > 0 && std::isfinite(len))) at.fail("makes the spot light's axis impossible to normalise in float");
    }
  };
  check_world(l.transform, at_transform ? *at_transform : at_position ? *at_position : ln);
  for (size_t k = 0; k < l.motion.size(); ++k) check_world(l.motion[k].matrix() * l.transform, at_motion->at(k));
  scene_.delta_lights.push_back(l);
}

bool same_material(const Material& a, const Material& b) {
  return a.name == b.name && a.type == b.type && is_black(a.albedo - b.albedo) && a.lobe == b.lobe &&
         a.roughness == b.roughness && a.exponent == b.exponent && a.ior == b.ior && is_black(a.eta - b.eta) &&
         is_black(a.k - b.k) && is_black(a.coat_color - b.coat_color) && a.coat_thickness == b.coat_thickness &&
         is_black(a.radiance - b.radiance) && a.two_sided == b.two_sided &&
         a.energy_compensation == b.energy_compensation && a.textures == b.textures;
}

void SceneParser::load_objs() {
  // Insert from the back so earlier slots stay valid.
  for (auto p = pending_.rbegin(); p != pending_.rend(); ++p) {
    ObjModel model = load_obj(p->path, p->material >= 0);
    scene_.degenerate_triangles += model.degenerate_triangles;
    if (model.parts.empty())
      p->file.fail(json_quoted(p->file.string()) + " has no triangles" +
                   (model.degenerate_triangles
                        ? " (all " + std::to_string(model.degenerate_triangles) + " are degenerate)"
                        : " (no f lines)"));
    std::vector<ShapeDesc> shapes;
    std::vector<ShapeDesc>& out = p->prototype >= 0 ? scene_.prototypes[size_t(p->prototype)].shapes : scene_.shapes;
    for (ObjPart& part : model.parts) {
      ShapeDesc s = p->placement;
      s.mesh = std::move(part.mesh);
      s.material = p->material;
      if (part.material) {
        // Objects sharing an OBJ share its materials.
        auto it = material_index_.find(part.material->name);
        if (it != material_index_.end() && same_material(scene_.materials[it->second], *part.material)) {
          s.material = it->second;
        } else {
          s.material = int(scene_.materials.size());
          material_index_[part.material->name] = s.material;
          scene_.materials.push_back(*part.material);
        }
      }
      if (p->prototype >= 0 && s.material >= 0 && part.material &&
          scene_.materials[size_t(s.material)].type == MaterialType::Emitter)
        p->file.fail(json_quoted(p->file.string()) + " has an emitting material (Ke) \"" + part.material->name +
                     "\"; emitters cannot be inside a prototype (instanced area lights are not supported)");
      shapes.push_back(std::move(s));
    }
    out.insert(out.begin() + std::ptrdiff_t(p->shape_slot), std::make_move_iterator(shapes.begin()),
               std::make_move_iterator(shapes.end()));
  }
}

}  // namespace

bool is_pbrt_scene(const fs::path& file) { return file.extension() == ".pbrt"; }

SceneDesc load_scene(const fs::path& file, bool strict) {
  if (is_pbrt_scene(file)) {
    PbrtImport imported = load_pbrt_scene(file, strict);
    for (const std::string& line : imported.report) warn(printable(line));
    check_render_settings(imported.scene);
    return std::move(imported.scene);
  }
  std::string reason;
  auto text = read_text_file(file, reason);
  if (!text) throw InputError(file.string() + ": cannot open: " + reason);
  JsonDocument doc(file.string(), std::move(*text));

  SceneParser parser(doc, file.parent_path());
  SceneDesc scene = parser.parse();
  scene.file = file;
  check_render_settings(scene);
  if (scene.degenerate_triangles > 0)
    warn(printable(doc.name()) + ": warning: skipped " + std::to_string(scene.degenerate_triangles) +
         " degenerate triangle" + (scene.degenerate_triangles == 1 ? "" : "s"));
  return scene;
}

}  // namespace pdrt
