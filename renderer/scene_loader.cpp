#include "scene_loader.h"

#include "errors.h"
#include "json_locations.h"
#include "obj_loader.h"
#include "text_file.h"

#include <nlohmann/json.hpp>

#include <cfloat>
#include <climits>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

namespace pdrt {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

std::string in_quotes(const std::string& s) { return json(s).dump(); }

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

// The scene text and how to point into it.
struct Source {
  std::string name;  // the scene path as given, for messages
  std::string text;
  JsonLocations locations{std::string_view()};

  [[noreturn]] void fail(const std::optional<JsonLocation>& at, const std::string& message) const {
    std::string where = at ? name + ":" + std::to_string(at->line) + ":" + std::to_string(at->col) : name;
    std::string line = where + ": " + message;
    for (char& c : line)
      if (c == '\n' || c == '\r') c = ' ';  // messages are one line
    throw InputError(line);
  }
};

class Object;

// A JSON value with its path; every accessor validates and fails with file:line:col.
class Node {
 public:
  Node(const Source& src, const json& v, std::string path) : src_(&src), v_(&v), path_(std::move(path)) {}
  const json& value() const { return *v_; }
  const std::string& path() const { return path_; }

  [[noreturn]] void fail(const std::string& what) const {
    src_->fail(src_->locations.value(path_), (path_.empty() ? "" : path_ + " ") + what);
  }
  [[noreturn]] void fail_got(const std::string& what) const { fail(what + ", got " + shown()); }
  [[noreturn]] void fail_key(const std::string& what) const {  // at the key naming this value
    src_->fail(src_->locations.key(path_), path_ + " " + what);
  }

  // Scalars as written (1e999 stays 1e999); containers abbreviated.
  std::string shown() const {
    if (!v_->is_structured()) {
      if (auto at = src_->locations.value(path_); at && at->end > at->begin) {
        std::string s(src_->locations.source(*at));
        return s.size() > 60 ? s.substr(0, 57) + "..." : s;
      }
    }
    std::string s = v_->dump();
    return s.size() > 60 ? s.substr(0, 57) + "..." : s;
  }

  float number() const {
    if (!v_->is_number()) fail_got("must be a number");
    double d = v_->get<double>();
    if (!std::isfinite(d)) fail_got("must be a finite number");
    if (std::abs(d) > FLT_MAX) fail_got("is too large for a float");
    return float(d);
  }
  float positive() const {
    float x = number();
    if (!(x > 0)) fail_got("must be > 0");
    return x;
  }
  float non_negative() const {
    float x = number();
    if (x < 0) fail_got("must be >= 0");
    return x;
  }
  float in_unit_interval() const {
    float x = number();
    if (x < 0 || x > 1) fail_got("must be in [0,1]");
    return x;
  }
  long long integer(long long lo, long long hi) const {
    if (!v_->is_number_integer()) fail_got("must be an integer");
    if (v_->is_number_unsigned() && v_->get<uint64_t>() > uint64_t(LLONG_MAX)) fail_got("must be <= " + std::to_string(hi));
    long long x = v_->get<long long>();
    if (x < lo) fail_got("must be an integer >= " + std::to_string(lo));
    if (x > hi) fail_got("must be an integer <= " + std::to_string(hi));
    return x;
  }
  int int_at_least(int lo) const { return int(integer(lo, INT_MAX)); }
  uint64_t unsigned_integer() const {
    if (!v_->is_number_unsigned()) fail_got("must be an unsigned integer");
    return v_->get<uint64_t>();
  }
  bool boolean() const {
    if (!v_->is_boolean()) fail_got("must be true or false");
    return v_->get<bool>();
  }
  std::string string() const {
    if (!v_->is_string()) fail_got("must be a string");
    return v_->get<std::string>();
  }
  std::string choice(std::initializer_list<const char*> options) const {
    std::string s = string(), list;
    for (const char* o : options) {
      if (s == o) return s;
      list += (list.empty() ? "" : ", ") + std::string(o);
    }
    fail_got("must be one of " + list);
  }
  Vec3 vec3() const {
    if (!v_->is_array() || v_->size() != 3) fail_got("must be an array of 3 numbers");
    return {at(0).number(), at(1).number(), at(2).number()};
  }
  Vec3 nonzero_vec3() const {
    Vec3 v = vec3();
    if (is_black(v)) fail_got("must be non-zero");
    return v;
  }
  Vec3 color() const {  // reflectances: each component in [0,1]
    Vec3 c = vec3();
    if (std::min({c.x, c.y, c.z}) < 0 || max_component(c) > 1) fail_got("must have components in [0,1]");
    return c;
  }
  Vec3 radiance() const {
    Vec3 c = vec3();
    if (std::min({c.x, c.y, c.z}) < 0) fail_got("must have components >= 0");
    return c;
  }
  size_t array_size(size_t min_size) const {
    if (!v_->is_array()) fail_got("must be an array");
    if (v_->size() < min_size) fail_got("must have at least " + std::to_string(min_size) + " elements");
    return v_->size();
  }
  Node at(size_t i) const { return Node(*src_, (*v_)[i], json_index_path(path_, i)); }
  Object object() const;

 private:
  friend class Object;
  const Source* src_;
  const json* v_;
  std::string path_;
};

// A JSON object whose keys are all checked against a list of allowed ones.
class Object {
 public:
  explicit Object(Node n) : node_(std::move(n)) {
    if (!node_.value().is_object()) node_.fail_got(node_.path().empty() ? "the scene must be a JSON object" : "must be an object");
  }
  const Node& node() const { return node_; }
  bool has(const std::string& key) const { return node_.value().contains(key); }
  Node child(const std::string& key) const {
    return Node(*src(), node_.value().at(key), json_key_path(node_.path(), key));
  }
  std::optional<Node> get(const std::string& key) const {
    if (!has(key)) return std::nullopt;
    return child(key);
  }
  Node require(const std::string& key) const {
    if (!has(key)) node_.fail("missing required key " + in_quotes(key));
    return child(key);
  }
  void allow(std::initializer_list<const char*> keys) const {
    for (auto it = node_.value().begin(); it != node_.value().end(); ++it) {
      const std::string& k = it.key();
      std::string best, list;
      size_t best_d = SIZE_MAX;
      bool ok = false;
      for (const char* a : keys) {
        if (k == a) ok = true;
        size_t d = edit_distance(k, a);
        if (d < best_d) best_d = d, best = a;
        list += (list.empty() ? "" : ", ") + std::string(a);
      }
      if (ok) continue;
      bool close = best_d <= 2 && best_d < k.size();
      child(k).fail_key(close ? "unknown key (did you mean " + in_quotes(best) + "?)" : "unknown key (expected one of: " + list + ")");
    }
  }

 private:
  const Source* src() const;
  Node node_;
};

Object Node::object() const { return Object(*this); }

class SceneParser {
 public:
  SceneParser(const Source& src, const json& root, fs::path dir) : src_(src), root_(src, root, ""), dir_(std::move(dir)) {}
  SceneDesc parse();

 private:
  void camera(const Object& o);
  void film(const Object& o);
  void sampler(const Object& o);
  void integrator(const Object& o);
  void materials(const Node& n);
  void objects(const Node& n);
  void lights(const Node& n);
  void load_objs();

  std::pair<float, float> shutter() const { return {scene_.camera.shutter_open, scene_.camera.shutter_close}; }
  int material_named(const Node& n) const;
  Affine transform(const Node& n) const;
  Affine rotation(const Node& n) const;
  Vec3 scale(const Node& n) const;
  std::vector<MotionKey> motion(const Node& n) const;
  void check_time(const Node& t, float previous, bool first) const;
  MeshData quad(const Object& o);
  void keep_triangles(MeshData& mesh, const Node& where);
  void place(ShapeDesc& s, const Object& o, const std::string& where) const;

  const Source& src_;
  Node root_;
  fs::path dir_;
  SceneDesc scene_;
  std::map<std::string, int> material_index_;

  struct PendingObj {  // OBJ files load after the whole JSON is validated
    size_t shape_slot;  // where in scene_.shapes its parts go
    fs::path path;
    Node file;
    int material;  // -1: the MTL's
    ShapeDesc placement;
  };
  std::vector<PendingObj> pending_;
};

const Source* Object::src() const { return node_.src_; }

SceneDesc SceneParser::parse() {
  Object top(root_);
  top.allow({"camera", "film", "sampler", "integrator", "materials", "objects", "lights"});
  camera(top.require("camera").object());
  film(top.require("film").object());
  if (auto n = top.get("sampler")) sampler(n->object());
  if (auto n = top.get("integrator")) integrator(n->object());
  if (auto n = top.get("materials")) materials(*n);
  if (auto n = top.get("objects")) objects(*n);
  if (auto n = top.get("lights")) lights(*n);
  load_objs();
  return std::move(scene_);
}

void SceneParser::camera(const Object& o) {
  o.allow({"position", "look_at", "up", "vfov_deg", "aperture_radius", "focus_distance", "aperture_blades",
           "aperture_rotation_deg", "shutter", "motion"});
  CameraDesc& c = scene_.camera;
  Node pos = o.require("position"), look = o.require("look_at");
  c.position = pos.vec3();
  c.look_at = look.vec3();
  std::optional<Node> up = o.get("up");
  if (up) c.up = up->nonzero_vec3();
  auto check_view = [&](const Vec3& p, const Vec3& l, const Node& at_look) {
    if (is_black(l - p)) at_look.fail_got("must differ from the position");
    Vec3 d = l - p;
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
  if (auto n = o.get("shutter")) {
    if (!n->value().is_array() || n->value().size() != 2) n->fail_got("must be [open, close]");
    c.shutter_open = n->at(0).number();
    c.shutter_close = n->at(1).number();
    if (c.shutter_open > c.shutter_close) n->fail_got("must have open <= close");
  }
  if (auto n = o.get("motion")) {
    size_t count = n->array_size(2);
    for (size_t i = 0; i < count; ++i) {
      Object k = n->at(i).object();
      k.allow({"time", "position", "look_at"});
      CameraKey key;
      Node t = k.require("time");
      check_time(t, i ? c.motion.back().time : 0, i == 0);
      key.time = t.number();
      key.position = k.require("position").vec3();
      Node kl = k.require("look_at");
      key.look_at = kl.vec3();
      check_view(key.position, key.look_at, kl);
      c.motion.push_back(key);
    }
  }
}

void SceneParser::check_time(const Node& t, float previous, bool first) const {
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

void SceneParser::film(const Object& o) {
  o.allow({"width", "height", "filter", "exposure"});
  FilmDesc& f = scene_.film;
  f.width = int(o.require("width").integer(1, 65536));
  f.height = int(o.require("height").integer(1, 65536));
  if (auto n = o.get("exposure")) f.exposure = n->number();
  if (auto n = o.get("filter")) {
    Object fo = n->object();
    fo.allow({"type", "radius", "selection"});
    std::string type = "gaussian";
    if (auto t = fo.get("type")) type = t->choice({"box", "tent", "gaussian", "mitchell"});
    static const std::map<std::string, std::pair<FilterType, float>> kinds = {
        {"box", {FilterType::Box, 0.5f}},
        {"tent", {FilterType::Tent, 1.0f}},
        {"gaussian", {FilterType::Gaussian, 1.5f}},
        {"mitchell", {FilterType::Mitchell, 2.0f}}};
    std::tie(f.filter.type, f.filter.radius) = kinds.at(type);
    if (auto r = fo.get("radius")) f.filter.radius = r->positive();
    if (auto s = fo.get("selection")) f.filter.rank_selection = s->choice({"weights", "rank"}) == "rank";
  }
}

void SceneParser::sampler(const Object& o) {
  o.allow({"type", "spp", "seed", "adaptive"});
  SamplerDesc& s = scene_.sampler;
  if (auto n = o.get("type")) s.type = n->choice({"random", "jitter", "poisson", "sobol"});
  if (auto n = o.get("spp")) s.spp = n->int_at_least(1);
  if (auto n = o.get("seed")) s.seed = n->unsigned_integer();
  if (auto n = o.get("adaptive")) {
    Object a = n->object();
    a.allow({"min_spp", "max_spp", "threshold", "metric"});
    s.adaptive.enabled = true;
    auto min_n = a.get("min_spp"), max_n = a.get("max_spp");
    if (min_n) s.adaptive.min_spp = min_n->int_at_least(1);
    if (max_n) s.adaptive.max_spp = max_n->int_at_least(1);
    if (s.adaptive.max_spp < s.adaptive.min_spp) {
      std::string bound = "must be >= min_spp (" + std::to_string(s.adaptive.min_spp) + ")";
      if (max_n) max_n->fail_got(bound);
      min_n->fail_got("must be <= max_spp (default " + std::to_string(s.adaptive.max_spp) + ")");
    }
    if (auto t = a.get("threshold")) s.adaptive.threshold = t->positive();
    if (auto m = a.get("metric")) s.adaptive.metric = m->choice({"relative-error", "contrast"});
  }
}

void SceneParser::integrator(const Object& o) {
  o.allow({"max_depth", "rr_depth"});
  if (auto n = o.get("max_depth")) scene_.integrator.max_depth = n->int_at_least(1);
  if (auto n = o.get("rr_depth")) scene_.integrator.rr_depth = n->int_at_least(1);
}

void SceneParser::materials(const Node& n) {
  Object all = n.object();
  for (auto it = n.value().begin(); it != n.value().end(); ++it) {
    Node mn = all.child(it.key());
    if (it.key().empty()) mn.fail_key("material name must not be empty");
    Object o = mn.object();
    Material m;
    m.name = it.key();
    std::string type = o.require("type").choice({"diffuse", "glossy", "mirror", "dielectric", "emitter"});
    if (type == "diffuse") {
      o.allow({"type", "albedo"});
      m.type = MaterialType::Diffuse;
      m.albedo = Vec3(0.8f);
    } else if (type == "glossy") {
      o.allow({"type", "albedo", "roughness", "exponent", "lobe"});
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
        m.roughness = rough->in_unit_interval();
      } else {
        m.lobe = GlossLobe::Phong;
        m.exponent = expo->positive();
      }
    } else if (type == "mirror") {
      o.allow({"type", "albedo"});
      m.type = MaterialType::Mirror;
      m.albedo = Vec3(1.0f);
    } else if (type == "dielectric") {
      o.allow({"type", "albedo", "ior", "roughness"});
      m.type = MaterialType::Dielectric;
      m.albedo = Vec3(1.0f);
      if (auto x = o.get("ior")) m.ior = x->positive();
      if (auto x = o.get("roughness")) m.roughness = x->in_unit_interval();
    } else {
      o.allow({"type", "radiance", "two_sided"});
      m.type = MaterialType::Emitter;
      m.radiance = o.require("radiance").radiance();
      if (auto x = o.get("two_sided")) m.two_sided = x->boolean();
    }
    if (auto a = o.get("albedo")) m.albedo = a->color();
    material_index_[m.name] = int(scene_.materials.size());
    scene_.materials.push_back(std::move(m));
  }
}

int SceneParser::material_named(const Node& n) const {
  std::string name = n.string();
  auto it = material_index_.find(name);
  if (it == material_index_.end()) n.fail("unknown material " + in_quotes(name));
  return it->second;
}

Vec3 SceneParser::scale(const Node& n) const {
  if (n.value().is_number()) {
    float s = n.number();
    if (s == 0) n.fail_got("must be non-zero");
    return Vec3(s);
  }
  Vec3 s = n.vec3();
  if (s.x == 0 || s.y == 0 || s.z == 0) n.fail_got("must have non-zero components");
  return s;
}

Affine SceneParser::rotation(const Node& n) const {
  Object o = n.object();
  o.allow({"axis", "degrees"});
  Vec3 axis = o.require("axis").nonzero_vec3();
  return Affine::rotate(axis, o.require("degrees").number());
}

Affine SceneParser::transform(const Node& n) const {
  Object o = n.object();
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

std::vector<MotionKey> SceneParser::motion(const Node& n) const {
  std::vector<MotionKey> keys;
  size_t count = n.array_size(2);
  for (size_t i = 0; i < count; ++i) {
    Object o = n.at(i).object();
    o.allow({"time", "translate", "rotate", "scale"});
    MotionKey k;
    Node t = o.require("time");
    check_time(t, i ? keys.back().time : 0, i == 0);
    k.time = t.number();
    if (auto x = o.get("translate")) k.translate = x->vec3();
    if (auto x = o.get("rotate")) {
      Object r = x->object();
      r.allow({"axis", "degrees"});
      Vec3 axis = r.require("axis").nonzero_vec3();
      k.rotate = Quat::from_axis_angle(axis, r.require("degrees").number());
    }
    if (auto x = o.get("scale")) k.scale = scale(*x);
    keys.push_back(k);
  }
  return keys;
}

void SceneParser::place(ShapeDesc& s, const Object& o, const std::string& where) const {
  if (auto t = o.get("transform")) s.transform = transform(*t);
  if (auto m = o.get("motion")) s.motion = motion(*m);
  s.where = src_.name + ": " + where;
}

MeshData SceneParser::quad(const Object& o) {
  Vec3 corner = o.require("corner").vec3();
  Node e1n = o.require("edge1"), e2n = o.require("edge2");
  Vec3 e1 = e1n.nonzero_vec3(), e2 = e2n.nonzero_vec3();
  if (is_black(cross(e1, e2))) e2n.fail_got("must not be parallel to edge1");
  MeshData m;
  m.positions = {corner, corner + e1, corner + e1 + e2, corner + e2};
  m.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise about cross(edge1, edge2)
  keep_triangles(m, e2n);
  return m;
}

// Drops degenerate triangles (repeated vertex, zero area) and counts them.
void SceneParser::keep_triangles(MeshData& mesh, const Node& where) {
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

void SceneParser::objects(const Node& n) {
  size_t count = n.array_size(0);
  for (size_t i = 0; i < count; ++i) {
    Node on = n.at(i);
    Object o = on.object();
    std::string type = o.require("type").choice({"sphere", "quad", "mesh", "obj"});
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
      o.allow({"type", "material", "transform", "motion", "vertices", "indices", "normals"});
      Node vn = o.require("vertices");
      size_t nv = vn.array_size(1);
      if (nv > UINT32_MAX) vn.fail("has too many vertices");
      s.mesh.positions.reserve(nv);
      for (size_t v = 0; v < nv; ++v) s.mesh.positions.push_back(vn.at(v).vec3());
      Node in = o.require("indices");
      size_t ni = in.array_size(3);
      if (ni % 3) in.fail("length must be a multiple of 3, got " + std::to_string(ni));
      s.mesh.indices.reserve(ni);
      for (size_t k = 0; k < ni; ++k) {
        const json& x = in.value()[k];  // fast path; build the element's Node only to report
        if (!x.is_number_unsigned() || x.get<uint64_t>() >= nv)
          in.at(k).fail_got("must be a vertex index in [0, " + std::to_string(nv - 1) + "]");
        s.mesh.indices.push_back(uint32_t(x.get<uint64_t>()));
      }
      if (auto nn = o.get("normals")) {
        if (nn->array_size(0) != nv) nn->fail("must have one normal per vertex (" + std::to_string(nv) + "), got " + std::to_string(nn->value().size()));
        for (size_t v = 0; v < nv; ++v) s.mesh.normals.push_back(nn->at(v).nonzero_vec3());
      }
      keep_triangles(s.mesh, in);
    } else {
      o.allow({"type", "material", "transform", "motion", "file"});
      Node file = o.require("file");
      fs::path path = dir_ / file.string();
      std::string reason;
      if (!can_open_file(path, reason)) file.fail("cannot open " + in_quotes(file.string()) + ": " + reason);
      int material = -1;
      if (auto m = o.get("material")) material = material_named(*m);
      place(s, o, on.path());
      pending_.push_back({scene_.shapes.size(), path, file, material, std::move(s)});
      continue;
    }
    s.material = material_named(o.require("material"));
    place(s, o, on.path());
    scene_.shapes.push_back(std::move(s));
  }
}

void SceneParser::lights(const Node& n) {
  size_t count = n.array_size(0);
  std::optional<Node> environment;
  for (size_t i = 0; i < count; ++i) {
    Node ln = n.at(i);
    Object o = ln.object();
    std::string type = o.require("type").choice({"quad", "sphere", "environment"});
    if (type == "environment") {
      o.allow({"type", "radiance"});
      if (environment) ln.fail("is a second environment light (at most one; the first is " + environment->path() + ")");
      environment = ln;
      scene_.environment.radiance = o.require("radiance").radiance();
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

bool same_material(const Material& a, const Material& b) {
  return a.name == b.name && a.type == b.type && is_black(a.albedo - b.albedo) && a.lobe == b.lobe &&
         a.roughness == b.roughness && a.exponent == b.exponent && a.ior == b.ior &&
         is_black(a.radiance - b.radiance) && a.two_sided == b.two_sided;
}

void SceneParser::load_objs() {
  // Insert from the back so earlier slots stay valid.
  for (auto p = pending_.rbegin(); p != pending_.rend(); ++p) {
    ObjModel model = load_obj(p->path, p->material >= 0);
    scene_.degenerate_triangles += model.degenerate_triangles;
    if (model.parts.empty())
      p->file.fail("has no triangles (all " + std::to_string(model.degenerate_triangles) + " skipped as degenerate)");
    std::vector<ShapeDesc> shapes;
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
      shapes.push_back(std::move(s));
    }
    scene_.shapes.insert(scene_.shapes.begin() + std::ptrdiff_t(p->shape_slot), std::make_move_iterator(shapes.begin()),
                         std::make_move_iterator(shapes.end()));
  }
}

// "[json.exception.parse_error.101] parse error at line 1, column 9: syntax error while
// parsing value - invalid literal; last read: 'tru}'" -> "JSON syntax error while parsing ...".
std::string short_reason(const std::string& what) {
  std::string r = what;
  if (size_t p = r.find("column "); p != std::string::npos)
    if (size_t c = r.find(": ", p); c != std::string::npos) r = r.substr(c + 2);
  const std::string prefix = "syntax error ";
  if (r.rfind(prefix, 0) == 0) r = r.substr(prefix.size());
  return "JSON syntax error " + r;
}

}  // namespace

SceneDesc load_scene(const fs::path& file) {
  Source src;
  src.name = file.string();
  std::string reason;
  auto text = read_text_file(file, reason);
  if (!text) throw InputError(src.name + ": cannot open: " + reason);
  src.text = std::move(*text);
  src.locations = JsonLocations(src.text);
  json root;
  try {
    root = json::parse(src.text);
  } catch (const json::parse_error& e) {
    src.fail(src.locations.at_byte(e.byte ? e.byte - 1 : 0), short_reason(e.what()));
  } catch (const json::out_of_range& e) {  // 406: a number beyond double range
    auto bad = src.locations.first_overflowing_number();
    if (!bad) throw InputError(src.name + ": " + e.what());
    src.fail(bad->second, bad->first + " must be a finite number, got " + std::string(src.locations.source(bad->second)));
  }
  if (auto dup = src.locations.first_duplicate_key()) src.fail(dup->second, dup->first + " duplicate key");

  SceneParser parser(src, root, file.parent_path());
  SceneDesc scene = parser.parse();
  scene.file = file;
  if (scene.degenerate_triangles > 0)
    std::cerr << src.name << ": warning: skipped " << scene.degenerate_triangles << " degenerate triangle"
              << (scene.degenerate_triangles == 1 ? "" : "s") << "\n";
  return scene;
}

}  // namespace pdrt
