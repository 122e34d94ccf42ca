#include "renderer/scene/pbrt/pbrt_scene_builder.h"

#include "renderer/scene/environment_image.h"
#include "renderer/scene/pbrt/equal_area_octahedral.h"
#include "renderer/scene/pbrt/loop_subdivision.h"
#include "renderer/scene/pbrt/pbrt_matrix.h"
#include "renderer/scene/pbrt/pbrt_spectrum.h"
#include "renderer/scene/pbrt/ply_mesh.h"
#include "renderer/scene/crop_window.h"
#include "renderer/scene/text_file.h"
#include "sampling/core/errors.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace pdrt {
namespace {

constexpr double kPiD = 3.14159265358979323846;

struct TransformPair {
  Mat4 t[2];  // at the shutter's start and end (TransformTimes)
};

struct AreaLight {
  Vec3 radiance;
  bool two_sided = false;
  PbrtLocation at;
};

struct Attributes {
  TransformPair ctm;
  bool active[2] = {true, true};
  bool reverse = false;
  int material = -1;  // index into the scene's materials; -1 = pbrt's default (diffuse 0.5)
  bool interface = false;  // the current material is "interface": shapes bound no surface
  std::optional<AreaLight> area;
  // Attribute "shape" | "light" | "material" | "texture": parameters every later directive of
  // that kind takes unless it sets them itself (pbrt-v4 file format, "Attributes").
  std::map<std::string, std::vector<PbrtParam>> defaults;
};

// The Attribute target a directive reads its defaults from ("" = none).
std::string attribute_target(const std::string& directive) {
  if (directive == "Shape") return "shape";
  if (directive == "LightSource" || directive == "AreaLightSource") return "light";
  if (directive == "Material" || directive == "MakeNamedMaterial") return "material";
  if (directive == "Texture") return "texture";
  return "";
}

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

class Builder {
 public:
  explicit Builder(bool strict) : strict_(strict) {}

  PbrtImport run(const std::vector<PbrtDirective>& ds) {
    for (const PbrtDirective& d : ds) {
      auto defaults = cur_.defaults.find(attribute_target(d.name));
      if (defaults == cur_.defaults.end()) {
        directive(d);
        report_unused(d.params.list);
        continue;
      }
      PbrtDirective with = d;
      for (const PbrtParam& p : defaults->second)
        if (!d.params.has(p.name)) with.params.list.push_back(p);
      directive(with);
      // An attribute one directive does not read may be meant for another: only the
      // directive's own parameters are reported unused.
      report_unused({with.params.list.begin(), with.params.list.begin() + long(d.params.list.size())});
    }
    if (!camera_seen_) {
      // pbrt-v4's default camera: perspective, fov 90, at the origin looking down +z.
      PbrtDirective d;
      d.name = "Camera";
      d.strings = {"perspective"};
      d.at = last_.value_or(PbrtLocation{});
      camera(d, TransformPair{}, true);
    }
    if (!attr_stack_.empty()) note(attr_stack_.back().first, "AttributeBegin is never closed (ignored)");
    drop_empty_prototypes();
    if (out_.scene.shapes.empty() && out_.scene.instances.empty() && out_.scene.delta_lights.empty() &&
        is_black(out_.scene.environment.radiance) && !out_.scene.environment.has_map())
      throw InputError((last_ ? last_->str() : std::string("<pbrt>")) + ": the scene has no shapes and no lights");
    return std::move(out_);
  }

 private:
  // Objects without a shape pdrt renders have no instances (skipped with a note): they go, and
  // the instances' indices follow.
  void drop_empty_prototypes() {
    std::vector<int> index(out_.scene.prototypes.size(), -1);
    std::vector<PrototypeDesc> kept;
    for (size_t i = 0; i < out_.scene.prototypes.size(); ++i)
      if (!out_.scene.prototypes[i].shapes.empty()) index[i] = int(kept.size()), kept.push_back(std::move(out_.scene.prototypes[i]));
    out_.scene.prototypes = std::move(kept);
    for (InstanceDesc& in : out_.scene.instances) in.prototype = index[size_t(in.prototype)];
  }

  // ---- reporting
  void report_unused(const std::vector<PbrtParam>& params) {
    for (const PbrtParam& p : params)
      if (!p.used) note(p.at, p.quoted() + " is not used by pdrt (ignored)");
  }
  void note(const PbrtLocation& at, const std::string& what) {
    std::string line = at.str() + ": " + what;
    if (strict_) throw InputError(line + " [--strict]");
    out_.report.push_back(line);
  }
  [[noreturn]] static void fail(const PbrtLocation& at, const std::string& what) { throw InputError(at.str() + ": " + what); }

  // ---- transforms
  void apply(const Mat4& m) {
    for (int i = 0; i < 2; ++i)
      if (cur_.active[i]) cur_.ctm.t[i] = cur_.ctm.t[i] * m;
  }
  void set(const Mat4& m) {
    for (int i = 0; i < 2; ++i)
      if (cur_.active[i]) cur_.ctm.t[i] = m;
  }
  bool moving() const { return !(cur_.ctm.t[0] == cur_.ctm.t[1]); }

  // Places a shape or light whose object space the CTM maps to world: a static transform, or
  // two keyframes at the TransformTimes.
  void place(const PbrtLocation& at, Affine* transform, std::vector<MotionKey>* motion) {
    for (const Mat4& m : cur_.ctm.t)
      if (!m.affine()) fail(at, "the current transform is projective; shapes and lights need an affine one");
    if (!moving()) {
      *transform = cur_.ctm.t[0].to_affine();
      return;
    }
    *transform = Affine{};
    motion->clear();
    for (int i = 0; i < 2; ++i) {
      double shear = 0;
      MotionKey k = decompose(cur_.ctm.t[i], &shear);
      if (shear > 1e-4) note(at, "the transform at time " + fmt(times_[i]) + " shears (dropped: pdrt's motion keys hold scale, rotation, translation)");
      k.time = float(times_[i]);
      motion->push_back(k);
    }
  }

  // ---- parameters
  Vec3 color(const PbrtParams& ps, const std::string& name, Vec3 fallback, bool emission) {
    const PbrtParam* p = ps.find(name);
    if (!p) return fallback;
    const std::string type = pbrt_canonical_type(p->type);
    p->used = true;
    if (type == "rgb") {
      if (p->numbers.size() != 3) fail(p->at, p->quoted() + " needs 3 values, got " + std::to_string(p->numbers.size()));
      Vec3 c{float(p->numbers[0]), float(p->numbers[1]), float(p->numbers[2])};
      for (int i = 0; i < 3; ++i)
        if (!(c[i] >= 0)) fail(p->at, "\"" + p->type + " " + name + "\" must have components >= 0, got " + fmt(c[i]));
      return c;
    }
    if (type == "blackbody") {
      if (p->numbers.size() != 1 || !(p->numbers[0] > 0))
        fail(p->at, "\"blackbody " + name + "\" takes one temperature > 0 (kelvin)");
      return blackbody_rgb(p->numbers[0]);
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
      return sampled_spectrum_to_rgb(p->numbers, emission);
    }
    if (type == "float" && p->numbers.size() == 1) return Vec3(float(p->numbers[0]));
    if (type == "texture") {
      if (!bind_to_) {
        note(p->at, "a texture for \"" + name + "\" is not supported here (default used)");
        return fallback;
      }
      if (auto t = texture_ref(*p, "spectrum")) bind_to_->push_back({bind_param_, *t});
      return fallback;
    }
    fail(p->at, p->quoted() + " must be rgb, spectrum, blackbody or a texture");
  }

  // "reflectance": an rgb/spectrum, or a texture bound to the material's albedo.
  Vec3 albedo(const PbrtParams& ps, Material& m) {
    bind_to_ = &m.textures, bind_param_ = MaterialParam::Albedo;
    Vec3 a = color(ps, "reflectance", Vec3(0.5f), false);
    bind_to_ = nullptr;
    return a;
  }

  float positive(const PbrtParams& ps, const std::string& name, float fallback, bool allow_zero = false) {
    std::optional<double> v = ps.find_float(name);
    if (!v) return fallback;
    if (!(allow_zero ? *v >= 0 : *v > 0) || !std::isfinite(*v))
      fail(ps.find(name)->at, "\"float " + name + "\" must be " + (allow_zero ? ">= 0" : "> 0") + ", got " + fmt(*v));
    return float(*v);
  }

  // pbrt-v4 roughness (alpha when remaproughness is false, else alpha = sqrt(roughness)) as
  // pdrt's perceptual roughness (alpha = roughness^2): roughness^(1/4) under remapping, else
  // roughness^(1/2). A texture is bound through a power texture of that exponent (after the
  // mean of uroughness and vroughness, when they differ): the filtered pbrt value is remapped
  // per hit, exactly as pbrt-v4 remaps its evaluated roughness texture.
  float roughness(const PbrtDirective& d, const PbrtParams& ps, Material& m) {
    struct Rough {
      double value = 0;
      int texture = -1;
      TextureInput input() const {
        TextureInput in;
        in.value = Vec3(float(value)), in.texture = texture;
        return in;
      }
    };
    auto one = [&](const char* n) -> std::optional<Rough> {
      const PbrtParam* p = ps.find(n);
      if (!p) return std::nullopt;
      Rough r;
      if (pbrt_canonical_type(p->type) == "texture") {
        p->used = true;
        if (auto t = texture_ref(*p, "float")) r.texture = *t;  // else reported, 0 used
        return r;
      }
      r.value = *ps.find_float(n);
      if (!(r.value >= 0) || !std::isfinite(r.value)) fail(p->at, std::string("\"float ") + n + "\" must be >= 0, got " + fmt(r.value));
      return r;
    };
    std::optional<Rough> r = one("roughness"), u = one("uroughness"), v = one("vroughness");
    const Rough ru = u ? *u : r.value_or(Rough{}), rv = v ? *v : r.value_or(Rough{});
    const bool remap = ps.get_bool("remaproughness", true);
    if (ru.texture < 0 && rv.texture < 0) {
      if (ru.value != rv.value)
        note(d.at, "anisotropic roughness (" + fmt(ru.value) + ", " + fmt(rv.value) + ") is not supported (their mean used)");
      double rough = 0.5 * (ru.value + rv.value);
      double alpha = remap ? std::sqrt(rough) : rough;
      return float(std::min(1.0, std::sqrt(alpha)));
    }
    TextureInput mean = ru.input();
    if (ru.texture != rv.texture || (ru.texture < 0 && ru.value != rv.value)) {
      note(d.at, "anisotropic roughness (uroughness and vroughness differ) is not supported (their mean used)");
      TextureDesc t;
      t.kind = TextureDesc::Kind::Mix;
      t.tex1 = ru.input(), t.tex2 = rv.input(), t.amount.value = Vec3(0.5f);
      mean.texture = add_texture(std::move(t), "mean roughness of " + m.name, d.at);
    }
    TextureDesc t;
    t.kind = TextureDesc::Kind::Power;
    t.tex = mean;
    t.exponent = remap ? 0.25f : 0.5f;
    m.textures.push_back({MaterialParam::Roughness, add_texture(std::move(t), "roughness of " + m.name, d.at)});
    return 0;
  }

  // A texture the importer adds (a roughness remap, an imagemap's scale or invert): appended
  // after its inputs, so the evaluation cost is known from theirs (kMaxTextureEvaluation).
  int add_texture(TextureDesc t, const std::string& name, const PbrtLocation& at) {
    t.name = name;
    t.where = at.str();
    const long long cost = texture_node_cost(t, texture_cost_);
    if (cost > kMaxTextureEvaluation)
      fail(at, "texture \"" + name + "\" evaluates " + (cost >= (1LL << 40) ? std::string("more than 2^40") : std::to_string(cost)) +
                   " scale/mix/invert/power nodes per lookup (at most " + std::to_string(kMaxTextureEvaluation) + ")");
    out_.scene.textures.push_back(std::move(t));
    texture_cost_.push_back(cost);
    return int(out_.scene.textures.size()) - 1;
  }

  // ---- directives
  void directive(const PbrtDirective& d) {
    last_ = d.at;
    const std::string& n = d.name;
    const auto& a = d.numbers;
    if (n == "Identity") return set(Mat4{});
    if (n == "Translate") return apply(Mat4::translate(a[0], a[1], a[2]));
    if (n == "Scale") return apply(Mat4::scale(a[0], a[1], a[2]));
    if (n == "Rotate") {
      if (a[1] == 0 && a[2] == 0 && a[3] == 0) fail(d.at, "Rotate needs a non-zero axis");
      return apply(Mat4::rotate(a[0], a[1], a[2], a[3]));
    }
    if (n == "LookAt") {
      auto m = Mat4::look_at({float(a[0]), float(a[1]), float(a[2])}, {float(a[3]), float(a[4]), float(a[5])},
                             {float(a[6]), float(a[7]), float(a[8])});
      if (!m) fail(d.at, "LookAt needs distinct eye and look points and an up vector not along the view");
      return apply(*m);
    }
    if (n == "Transform") return set(Mat4::from_pbrt(a.data()));
    if (n == "ConcatTransform") return apply(Mat4::from_pbrt(a.data()));
    if (n == "CoordinateSystem") {
      named_[d.strings[0]] = cur_.ctm;
      return;
    }
    if (n == "CoordSysTransform") {
      auto it = named_.find(d.strings[0]);
      if (it == named_.end()) fail(d.at, "unknown coordinate system \"" + d.strings[0] + "\"");
      for (int i = 0; i < 2; ++i)
        if (cur_.active[i]) cur_.ctm.t[i] = it->second.t[i];
      return;
    }
    if (n == "ActiveTransform") {
      cur_.active[0] = d.strings[0] != "EndTime";
      cur_.active[1] = d.strings[0] != "StartTime";
      return;
    }
    if (n == "TransformTimes") {
      if (in_world_) fail(d.at, "TransformTimes must come before WorldBegin");
      if (!(a[0] <= a[1])) fail(d.at, "TransformTimes needs start <= end, got " + fmt(a[0]) + " > " + fmt(a[1]));
      times_[0] = a[0], times_[1] = a[1];
      return;
    }
    if (n == "ReverseOrientation") {
      cur_.reverse = !cur_.reverse;
      return;
    }
    if (n == "AttributeBegin" || n == "TransformBegin") {
      attr_stack_.push_back({d.at, cur_});
      attr_kind_.push_back(n == "TransformBegin");
      return;
    }
    if (n == "AttributeEnd" || n == "TransformEnd") {
      if (attr_stack_.empty()) fail(d.at, n + " without a matching " + (n == "AttributeEnd" ? "AttributeBegin" : "TransformBegin"));
      const bool transform_only = attr_kind_.back();
      if (transform_only != (n == "TransformEnd"))
        fail(d.at, n + " closes the " + (transform_only ? "TransformBegin" : "AttributeBegin") + " at " + attr_stack_.back().first.str());
      if (transform_only) {
        cur_.ctm = attr_stack_.back().second.ctm;
        std::copy(attr_stack_.back().second.active, attr_stack_.back().second.active + 2, cur_.active);
      } else {
        cur_ = attr_stack_.back().second;
      }
      attr_stack_.pop_back();
      attr_kind_.pop_back();
      return;
    }
    if (n == "Camera") return camera(d, cur_.ctm);
    if (n == "Film") return film(d);
    if (n == "PixelFilter") return filter(d);
    if (n == "Sampler") return sampler(d);
    if (n == "Integrator") return integrator(d);
    if (n == "Accelerator") return;  // pdrt always builds Embree's BVH; its parameters are reported unused
    if (n == "ColorSpace") {
      if (d.strings[0] != "srgb") note(d.at, "ColorSpace \"" + d.strings[0] + "\" is not supported (pdrt renders linear sRGB)");
      return;
    }
    if (n == "Option") return;  // reported as unused parameters
    if (n == "WorldBegin") {
      if (in_world_) fail(d.at, "a second WorldBegin");
      in_world_ = true;
      named_["world"] = TransformPair{};
      cur_.ctm = TransformPair{};
      return;
    }
    if (n == "WorldEnd") return;  // pbrt-v3
    if (n == "MakeNamedMedium" || n == "MediumInterface") {
      note(d.at, n + " is not supported: pdrt has no participating media (ignored)");
      for (const PbrtParam& p : d.params.list) p.used = true;
      return;
    }
    if (n == "Attribute") {
      const std::string& target = d.strings[0];
      if (target == "medium") {
        note(d.at, "Attribute \"medium\" is not supported: pdrt has no participating media (ignored)");
      } else if (target != "shape" && target != "light" && target != "material" && target != "texture") {
        fail(d.at, "Attribute target must be \"shape\", \"light\", \"material\", \"medium\" or \"texture\", got \"" + target + "\"");
      } else {
        std::vector<PbrtParam>& list = cur_.defaults[target];
        for (const PbrtParam& p : d.params.list) {
          std::erase_if(list, [&](const PbrtParam& q) { return q.name == p.name; });
          list.push_back(p);
        }
      }
      for (const PbrtParam& p : d.params.list) p.used = true;
      return;
    }
    if (n == "Texture") return texture(d);
    if (!in_world_ && (n == "Material" || n == "MakeNamedMaterial" || n == "NamedMaterial" || n == "Shape" ||
                       n == "LightSource" || n == "AreaLightSource" || n == "ObjectBegin" || n == "ObjectInstance"))
      fail(d.at, n + " must come after WorldBegin");
    if (n == "Material") {
      int m = material(d, d.strings[0], d.params, "material at " + d.at.str());
      cur_.interface = m == -2;
      cur_.material = m == -2 ? -1 : m;
      return;
    }
    if (n == "MakeNamedMaterial") {
      std::optional<std::string> type = d.params.find_string("type");
      if (!type) fail(d.at, "MakeNamedMaterial \"" + d.strings[0] + "\" needs \"string type\"");
      named_materials_[d.strings[0]] = material(d, *type, d.params, d.strings[0]);
      return;
    }
    if (n == "NamedMaterial") {
      auto it = named_materials_.find(d.strings[0]);
      if (it == named_materials_.end()) fail(d.at, "unknown named material \"" + d.strings[0] + "\"");
      cur_.interface = it->second == -2;
      cur_.material = it->second == -2 ? -1 : it->second;
      return;
    }
    if (n == "AreaLightSource") {
      if (d.strings[0] != "diffuse") {
        note(d.at, "AreaLightSource \"" + d.strings[0] + "\" is not supported (no emission)");
        for (const PbrtParam& p : d.params.list) p.used = true;
        cur_.area.reset();
        return;
      }
      AreaLight l;
      l.at = d.at;
      Vec3 L = color(d.params, "L", Vec3(1.0f), true);
      float scale = float(d.params.get_float("scale", 1));
      if (!(scale >= 0)) fail(d.at, "\"float scale\" must be >= 0");
      if (d.params.find_float("power")) note(d.params.find("power")->at, "\"power\" of an area light is not supported (ignored)");
      l.radiance = L * scale;
      l.two_sided = d.params.get_bool("twosided", false);
      cur_.area = l;
      return;
    }
    if (n == "LightSource") return light(d);
    if (n == "Shape") return shape(d);
    if (n == "ObjectBegin") {
      if (object_) fail(d.at, "ObjectBegin inside the ObjectBegin at " + object_at_.str());
      attr_stack_.push_back({d.at, cur_});
      attr_kind_.push_back(false);
      object_ = d.strings[0];
      object_at_ = d.at;
      if (objects_.count(*object_)) fail(d.at, "object \"" + *object_ + "\" is defined twice");
      // A prototype (SceneDesc::prototypes): its shapes are stored once, traced through
      // Embree instances.
      objects_[*object_] = int(out_.scene.prototypes.size());
      PrototypeDesc proto;
      proto.name = *object_;
      proto.where = d.at.str();
      out_.scene.prototypes.push_back(std::move(proto));
      return;
    }
    if (n == "ObjectEnd") {
      if (!object_) fail(d.at, "ObjectEnd without ObjectBegin");
      object_.reset();
      cur_ = attr_stack_.back().second;
      attr_stack_.pop_back();
      attr_kind_.pop_back();
      return;
    }
    if (n == "ObjectInstance") {
      if (object_) fail(d.at, "ObjectInstance inside an object definition");
      auto it = objects_.find(d.strings[0]);
      if (it == objects_.end()) fail(d.at, "unknown object \"" + d.strings[0] + "\"");
      if (out_.scene.prototypes[size_t(it->second)].shapes.empty()) {
        note(d.at, "object \"" + d.strings[0] + "\" has no shapes pdrt can render (instance skipped)");
        return;
      }
      // pbrt-v4's BasicSceneBuilder::ObjectInstance: render-from-instance is the CTM here (at
      // the two TransformTimes when it moves), applied on top of the object's shapes' own CTMs.
      InstanceDesc inst;
      inst.prototype = it->second;
      place(d.at, &inst.transform, &inst.motion);
      if (!inst.motion.empty() && !(times_[0] >= out_.scene.camera.shutter_open && times_[1] <= out_.scene.camera.shutter_close))
        note(d.at, "motion keys at TransformTimes outside the camera's shutter (the instance's motion is clamped to the shutter)");
      inst.where = d.at.str();
      out_.scene.instances.push_back(std::move(inst));
      return;
    }
    fail(d.at, "directive " + n + " is not handled");  // the parser knows no other names
  }

  // A texture parameter's texture, or nullopt when it names none we have (reported).
  std::optional<int> texture_ref(const PbrtParam& p, const std::string& kind) {
    auto it = textures_.find(kind + ":" + p.strings[0]);
    if (it == textures_.end()) it = textures_.find((kind == "float" ? "spectrum:" : "float:") + p.strings[0]);
    if (it == textures_.end()) fail(p.at, "unknown texture \"" + p.strings[0] + "\"");
    if (it->second < 0) {
      note(p.at, "texture \"" + p.strings[0] + "\" is not supported (the default value is used)");
      return std::nullopt;
    }
    return it->second;
  }

  // A texture input of a checkerboard: a number, an rgb or a texture.
  TextureInput texture_input(const PbrtParams& ps, const std::string& name, float fallback, const std::string& kind) {
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

  void texture(const PbrtDirective& d) {
    const PbrtParams& ps = d.params;
    const std::string& kind = d.strings[1], &cls = d.strings[2];
    if (kind != "float" && kind != "spectrum") fail(d.at, "a texture's type must be \"float\" or \"spectrum\", got \"" + kind + "\"");
    const std::string key = kind + ":" + d.strings[0];
    TextureDesc t;
    t.name = d.strings[0];
    t.where = d.at.str();
    bool supported = true;
    if (const std::optional<std::string> mapping = ps.find_string("mapping"); mapping && *mapping != "uv") {
      note(ps.find("mapping")->at, "texture mapping \"" + *mapping + "\" is not supported (skipped)");
      supported = false;
    }
    t.scale_u = float(ps.get_float("uscale", 1)), t.scale_v = float(ps.get_float("vscale", 1));
    if (!(t.scale_u > 0 && t.scale_v > 0)) fail(d.at, "\"uscale\" and \"vscale\" must be > 0");
    for (const char* k : {"udelta", "vdelta"})
      if (ps.get_float(k, 0) != 0) note(ps.find(k)->at, std::string("\"") + k + "\" is not supported (0 used)");
    // pbrt-v4's ScaleTexture and MixTexture (their inputs come before them: no cycles).
    auto non_negative = [&](const char* name, float fallback) {
      TextureInput in = texture_input(ps, name, fallback, kind);
      for (int c = 0; c < 3; ++c)
        if (!(in.value[c] >= 0)) fail(ps.find(name)->at, std::string("\"") + name + "\" must be >= 0, got " + fmt(in.value[c]));
      return in;
    };
    if (cls == "scale") {
      t.kind = TextureDesc::Kind::Scale;
      t.tex = non_negative("tex", 1);
      t.scale = non_negative("scale", 1);
    } else if (cls == "mix") {
      t.kind = TextureDesc::Kind::Mix;
      t.tex1 = non_negative("tex1", 0);
      t.tex2 = non_negative("tex2", 1);
      t.amount = texture_input(ps, "amount", 0.5f, "float");
    } else if (cls == "constant") {
      t.kind = TextureDesc::Kind::Constant;
      t.value = color(ps, "value", Vec3(1.0f), false);
    } else if (cls == "checkerboard") {
      t.kind = TextureDesc::Kind::Checkerboard;
      if (ps.get_int("dimension", 2) != 2) {
        note(d.at, "3-D checkerboards are not supported (skipped)");
        supported = false;
      }
      t.color0 = texture_input(ps, "tex1", 1, kind);
      t.color1 = texture_input(ps, "tex2", 0, kind);
    } else if (cls == "imagemap") {
      t.kind = TextureDesc::Kind::Image;
      std::optional<std::string> name = ps.find_string("filename");
      if (!name) fail(d.at, "Texture \"imagemap\" needs \"string filename\"");
      const std::filesystem::path rel = d.at.file ? std::filesystem::path(*d.at.file).parent_path() : std::filesystem::path();
      t.file = std::filesystem::path(*name).is_absolute() ? std::filesystem::path(*name) : rel / *name;
      std::string reason;
      if (!can_open_file(t.file, reason)) fail(ps.find("filename")->at, "cannot open \"" + t.file.string() + "\": " + reason);
      const std::string filter = ps.get_string("filter", "bilinear");
      if (filter == "point") t.filter = TextureFilter::None;
      else if (filter == "bilinear") t.filter = TextureFilter::Bilinear;
      else if (filter == "trilinear") t.filter = TextureFilter::Trilinear;
      else if (filter == "ewa") t.filter = TextureFilter::Ewa;
      else fail(ps.find("filter")->at, "unknown filter \"" + filter + "\" (point, bilinear, trilinear, ewa)");
      const std::string wrap = ps.get_string("wrap", "repeat");
      if (wrap == "repeat") t.wrap = TextureWrap::Repeat;
      else if (wrap == "black") t.wrap = TextureWrap::Black;
      else if (wrap == "clamp") t.wrap = TextureWrap::Clamp;
      else {
        note(ps.find("wrap")->at, "wrap \"" + wrap + "\" is not supported (repeat used)");
      }
      if (std::optional<std::string> enc = ps.find_string("encoding")) {
        if (*enc == "sRGB") t.encoding = TextureEncoding::Srgb;
        else if (*enc == "linear") t.encoding = TextureEncoding::Linear;
        else note(ps.find("encoding")->at, "encoding \"" + *enc + "\" is not supported (sRGB for 8-bit files, else linear)");
      }
      // pbrt-v4's image textures: ClampZero(invert ? 1 - scale x : scale x), as a scale and an
      // invert texture on top of the image (the name then means the outermost).
      const double scale = ps.get_float("scale", 1);
      if (!(scale >= 0) || !std::isfinite(scale)) fail(ps.find("scale")->at, "\"float scale\" must be >= 0, got " + fmt(scale));
      const bool invert = ps.get_bool("invert", false);
      if (scale != 1 || invert) {
        TextureInput in;
        in.texture = add_texture(std::move(t), d.strings[0] + " (image)", d.at);
        t = TextureDesc{};
        t.name = d.strings[0], t.where = d.at.str();
        if (scale != 1) {
          t.kind = TextureDesc::Kind::Scale;
          t.tex = in, t.scale.value = Vec3(float(scale));
          if (invert) {
            in.texture = add_texture(std::move(t), d.strings[0] + " (scaled image)", d.at);
            t = TextureDesc{};
            t.name = d.strings[0], t.where = d.at.str();
          }
        }
        if (invert) t.kind = TextureDesc::Kind::Invert, t.tex = in;
      }
    } else {
      note(d.at, "Texture class \"" + cls + "\" is not supported (materials using it get their default value)");
      supported = false;
    }
    if (!supported) {
      for (const PbrtParam& p : ps.list) p.used = true;
      textures_[key] = -1;
      return;
    }
    const std::string name = t.name;
    textures_[key] = add_texture(std::move(t), name, d.at);
  }

  void camera(const PbrtDirective& d, const TransformPair& camera_from_world, bool implicit = false) {
    if (camera_seen_) fail(d.at, "a second Camera");
    if (in_world_ && !implicit) fail(d.at, "Camera must come before WorldBegin");
    camera_seen_ = true;
    named_["camera"] = camera_from_world;
    CameraDesc& c = out_.scene.camera;
    const PbrtParams& ps = d.params;
    if (d.strings[0] == "orthographic") {
      c.projection = CameraDesc::Projection::Orthographic;
      if (ps.get_float("lensradius", 0) > 0)
        note(ps.find("lensradius")->at, "orthographic depth of field moves each ray's own origin by the lens offset "
                                        "(pbrt-v4 starts every ray at the lens offset from the camera's centre, "
                                        "mmp/pbrt-v3#315): out-of-focus blur differs");
    } else if (d.strings[0] != "perspective") {
      note(d.at, "Camera \"" + d.strings[0] + "\" is not supported (a perspective camera is used)");
      for (const PbrtParam& p : ps.list) p.used = true;
    }
    Mat4 world_from_camera[2];
    for (int i = 0; i < 2; ++i) {
      auto inv = camera_from_world.t[i].inverse();
      if (!inv || !inv->affine()) fail(d.at, "the camera transform is singular or projective");
      world_from_camera[i] = *inv;
    }
    auto pose = [&](const Mat4& w, Vec3* pos, Vec3* fwd, Vec3* up, Vec3* right) {
      *pos = w.point({0, 0, 0});
      *fwd = normalize(w.vector({0, 0, 1}));
      *up = normalize(w.vector({0, 1, 0}));
      *right = w.vector({1, 0, 0});
    };
    Vec3 pos, fwd, up, right;
    pose(world_from_camera[0], &pos, &fwd, &up, &right);
    // Camera-space lengths in scene units: the orthographic screen window is in camera space.
    camera_scale_ = {length(right), length(world_from_camera[0].vector({0, 1, 0}))};
    c.position = pos;
    c.up = up;
    // pbrt's raster x follows camera +x; pdrt's follows forward x up unless flipped.
    c.flip_x = dot(right, cross(fwd, up)) < 0;
    const float focal = positive(ps, "focaldistance", 1e6f);
    c.look_at = pos + fwd;
    c.focus_distance = focal;
    c.aperture_radius = positive(ps, "lensradius", 0, true);
    float open = float(ps.get_float("shutteropen", 0)), close = float(ps.get_float("shutterclose", 1));
    if (!(open <= close)) fail(d.at, "shutteropen must be <= shutterclose");
    c.shutter_open = open, c.shutter_close = close;
    if (!(camera_from_world.t[0] == camera_from_world.t[1])) {
      Vec3 p1, f1, u1, r1;
      pose(world_from_camera[1], &p1, &f1, &u1, &r1);
      if (length(u1 - up) > 1e-4f) note(d.at, "the camera's up vector turns during the shutter (pdrt keeps the start's)");
      c.motion = {{float(times_[0]), pos, pos + fwd}, {float(times_[1]), p1, p1 + f1}};
      if (!(times_[0] >= open && times_[1] <= close) || times_[0] == times_[1]) {
        note(d.at, "camera motion keys at TransformTimes " + fmt(times_[0]) + ", " + fmt(times_[1]) +
                       " outside the shutter or at one time (camera motion dropped)");
        c.motion.clear();
      }
    }
    if (c.projection == CameraDesc::Projection::Perspective) {
      fov_ = float(ps.get_float("fov", 90));
      if (!(fov_ > 0 && fov_ < 180)) fail(ps.find("fov")->at, "\"float fov\" must be in (0, 180), got " + fmt(fov_));
    }
    screen_params(ps);
    camera_at_ = d.at;
  }

  // pbrt-v4 CameraBase: "screenwindow" [x0 x1 y0 y1] in screen space and "frameaspectratio",
  // resolved against the film in resolve_screen() once its resolution is known.
  void screen_params(const PbrtParams& ps) {
    if (const PbrtParam* p = ps.find("screenwindow")) {
      std::vector<double> w = ps.floats("screenwindow");
      p->used = true;
      if (w.size() != 4) fail(p->at, "\"float screenwindow\" needs 4 values [x0 x1 y0 y1], got " + std::to_string(w.size()));
      for (double v : w)
        if (!(std::abs(v) <= 1e6)) fail(p->at, "\"float screenwindow\" values must be finite, within [-1e6, 1e6], got " + fmt(v));
      if (!(w[0] < w[1] && w[2] < w[3])) fail(p->at, "\"float screenwindow\" must have x0 < x1 and y0 < y1");
      screen_window_ = {float(w[0]), float(w[1]), float(w[2]), float(w[3])};
    }
    if (ps.find("frameaspectratio")) frame_aspect_ = positive(ps, "frameaspectratio", 1);
  }

  void film(const PbrtDirective& d) {
    if (d.strings[0] != "rgb" && d.strings[0] != "gbuffer")
      note(d.at, "Film \"" + d.strings[0] + "\" is not supported (rgb used)");
    const PbrtParams& ps = d.params;
    auto res = [&](const char* name, int fallback) {
      std::optional<int64_t> v = ps.find_int(name);
      if (!v) return fallback;
      if (*v < 1 || *v > 65536) fail(ps.find(name)->at, std::string("\"integer ") + name + "\" must be in [1, 65536], got " + std::to_string(*v));
      return int(*v);
    };
    out_.scene.film.width = res("xresolution", 1280);
    out_.scene.film.height = res("yresolution", 720);
    if (const PbrtParam* p = ps.find("filename")) p->used = true;  // pdrt render -o names the output
    crop(ps);
    for (const char* k : {"iso", "exposuretime", "whitebalance"})
      if (const PbrtParam* p = ps.find(k)) {
        p->used = true;
        note(p->at, std::string("\"") + k + "\" is not supported (ignored)");
      }
  }

  // pbrt-v4 FilmBaseParameters: "pixelbounds" [x0 x1 y0 y1] in pixels (each pair sorted,
  // clamped to the film) or "cropwindow" [x0 x1 y0 y1] (each pair sorted, clamped to [0, 1];
  // wins when both are given).
  void crop(const PbrtParams& ps) {
    FilmDesc& f = out_.scene.film;
    const PbrtParam* cw = ps.find("cropwindow");
    const PbrtParam* pb = ps.find("pixelbounds");
    if (pb) {
      std::vector<int64_t> b = ps.ints("pixelbounds");
      pb->used = true;
      if (b.size() != 4) fail(pb->at, "\"integer pixelbounds\" needs 4 values [x0 x1 y0 y1], got " + std::to_string(b.size()));
      if (cw) note(pb->at, "both \"cropwindow\" and \"pixelbounds\" (the crop window used, as pbrt-v4)");
      auto clamp = [](int64_t v, int hi) { return int(std::clamp<int64_t>(v, 0, hi)); };
      f.crop_window = crop_window_for_pixels(clamp(std::min(b[0], b[1]), f.width), clamp(std::max(b[0], b[1]), f.width),
                                             clamp(std::min(b[2], b[3]), f.height), clamp(std::max(b[2], b[3]), f.height),
                                             f.width, f.height);
    }
    if (cw) {
      std::vector<double> c = ps.floats("cropwindow");
      cw->used = true;
      if (c.size() != 4) fail(cw->at, "\"float cropwindow\" needs 4 values [x0 x1 y0 y1], got " + std::to_string(c.size()));
      for (double v : c)
        if (!std::isfinite(v)) fail(cw->at, "\"float cropwindow\" values must be finite, got " + fmt(v));
      auto unit = [](double v) { return float(std::clamp(v, 0.0, 1.0)); };
      f.crop_window = {unit(std::min(c[0], c[1])), unit(std::max(c[0], c[1])), unit(std::min(c[2], c[3])),
                       unit(std::max(c[2], c[3]))};
    }
    if (crop_pixels(f.crop_window, f.width, f.height).empty())
      fail((cw ? cw : pb)->at, std::string(cw ? "\"float cropwindow\"" : "\"integer pixelbounds\"") + " covers no pixel of the " +
                                   std::to_string(f.width) + "x" + std::to_string(f.height) + " film");
  }

  void filter(const PbrtDirective& d) {
    FilterDesc& f = out_.scene.film.filter;
    const std::string& t = d.strings[0];
    float def = 0.5f;
    if (t == "box") f.type = FilterType::Box, def = 0.5f;
    else if (t == "gaussian") f.type = FilterType::Gaussian, def = 1.5f;
    else if (t == "mitchell") f.type = FilterType::Mitchell, def = 2;
    else if (t == "triangle") f.type = FilterType::Tent, def = 2;
    else {
      note(d.at, "PixelFilter \"" + t + "\" is not supported (gaussian used)");
      f.type = FilterType::Gaussian, def = 1.5f;
      for (const PbrtParam& p : d.params.list) p.used = true;
    }
    const float rx = positive(d.params, "xradius", def), ry = positive(d.params, "yradius", def);
    if (rx != ry) note(d.at, "different x and y filter radii are not supported (their mean used)");
    f.radius = 0.5f * (rx + ry);
    if (t == "gaussian" && d.params.has("sigma"))
      note(d.params.find("sigma")->at, "\"sigma\" is not supported: pdrt's Gaussian is Cook's exp(-d^2) (ignored)");
    if (t == "mitchell")
      for (const char* k : {"B", "C"})
        if (auto v = d.params.find_float(k); v && std::abs(*v - 1.0 / 3) > 1e-6)
          note(d.params.find(k)->at, std::string("Mitchell ") + k + " other than 1/3 is not supported (1/3 used)");
  }

  void sampler(const PbrtDirective& d) {
    const std::string& t = d.strings[0];
    SamplerDesc& s = out_.scene.sampler;
    if (t == "zsobol" || t == "sobol" || t == "paddedsobol" || t == "halton") s.type = "sobol";
    else if (t == "pmj02bn") s.type = "poisson";
    else if (t == "stratified") s.type = "jitter";
    else if (t == "independent") s.type = "random";
    else note(d.at, "Sampler \"" + t + "\" is unknown (poisson used)");
    int64_t spp = 16;
    if (t == "stratified") {
      // Each factor on its own first: the product of two large ones would overflow.
      const int64_t xs = d.params.get_int("xsamples", 4), ys = d.params.get_int("ysamples", 4);
      if (xs < 1 || ys < 1 || xs > (int64_t(1) << 24) || ys > (int64_t(1) << 24))
        fail(d.at, "\"integer xsamples\" and \"integer ysamples\" must be in [1, 2^24], got " + std::to_string(xs) +
                       " and " + std::to_string(ys));
      spp = xs * ys;
      d.params.find_bool("jitter");
    } else {
      spp = d.params.get_int("pixelsamples", 16);
    }
    if (spp < 1 || spp > (int64_t(1) << 24)) fail(d.at, "the sample count must be in [1, 2^24], got " + std::to_string(spp));
    s.spp = int(spp);
    if (auto seed = d.params.find_int("seed")) s.seed = uint64_t(*seed);
    d.params.find_string("randomization");
  }

  void integrator(const PbrtDirective& d) {
    const std::string& t = d.strings[0];
    if (t != "path" && t != "volpath")
      fail(d.at, "Integrator \"" + t + "\" is not supported: pdrt is a unidirectional path tracer (use \"path\" or \"volpath\")");
    int64_t depth = d.params.get_int("maxdepth", 5);
    if (depth < 1 || depth > 100000) fail(d.at, "\"integer maxdepth\" must be in [1, 100000], got " + std::to_string(depth));
    out_.scene.integrator.max_depth = int(depth);
    if (auto v = d.params.find_string("lightsampler"); v && *v != "bvh")
      note(d.params.find("lightsampler")->at, "light sampler \"" + *v + "\" is not supported (pdrt's BVH light sampler used)");
    if (auto r = d.params.find_bool("regularize")) out_.scene.integrator.regularize = *r;
  }

  // Returns the material's index, or -2 for "interface" (a medium boundary, no surface).
  int material(const PbrtDirective& d, const std::string& type, const PbrtParams& ps, const std::string& name) {
    Material m;
    m.name = name;
    for (const char* k : {"displacement", "normalmap"})
      if (const PbrtParam* p = ps.find(k)) {
        p->used = true;
        note(p->at, std::string("\"") + k + "\" is not supported (ignored)");
      }
    if (type == "" || type == "none" || type == "interface") return -2;
    if (type == "diffuse") {
      m.type = MaterialType::Diffuse;
      m.albedo = albedo(ps, m);
    } else if (type == "conductor" || type == "coatedconductor") {
      if (type == "coatedconductor") note(d.at, "coatedconductor is not supported (its conductor is used, without the coat)");
      m.type = MaterialType::Conductor;
      m.roughness = roughness(d, ps, m);
      const std::string pre = type == "coatedconductor" ? "conductor." : "";
      const PbrtParam* refl = ps.find(pre + "reflectance");
      if (refl) {
        // F0 = r for eta = 1, k = 2 sqrt(r) / sqrt(1 - r) (pbrt-v4 does the same); a texture
        // binds the same mapping per hit (MaterialParam::Reflectance).
        bind_to_ = &m.textures, bind_param_ = MaterialParam::Reflectance;
        Vec3 r = color(ps, pre + "reflectance", Vec3(0.0f), false);
        bind_to_ = nullptr;
        conductor_from_reflectance(r, &m);
      } else {
        m.eta = metal_param(ps, pre + "eta", true);
        m.k = metal_param(ps, pre + "k", false);
      }
    } else if (type == "coateddiffuse") {
      // pbrt-v4's random-walk layers as pdrt's analytic coat: the same base reflectance, coat
      // roughness and index; the medium between the layers, absorbing by default (albedo 0),
      // becomes the coat's Beer-Lambert transmittance exp(-thickness) per pass.
      m.type = MaterialType::CoatedDiffuse;
      m.albedo = albedo(ps, m);
      for (int c = 0; c < 3; ++c) m.albedo[c] = std::min(m.albedo[c], 1.0f);
      m.roughness = roughness(d, ps, m);
      float eta = index_of_refraction(ps);
      if (eta < 1 || eta > 3) {
        note(d.at, "a coat index of " + fmt(eta) + " is outside pdrt's [1, 3] (clamped)");
        eta = std::clamp(eta, 1.0f, 3.0f);
      }
      m.ior = eta;
      const float thickness = positive(ps, "thickness", 0.01f, true);
      const Vec3 medium = color(ps, "albedo", Vec3(0.0f), false);
      if (!is_black(medium)) note(d.at, "a scattering medium in the coat (\"albedo\") is not supported (it only absorbs)");
      m.coat_color = Vec3(std::exp(-thickness));
      m.coat_thickness = 1;
      for (const char* k : {"g", "maxdepth", "nsamples"}) ps.find(k) && (ps.find(k)->used = true);
    } else if (type == "dielectric") {
      m.type = MaterialType::Dielectric;
      m.albedo = Vec3(1.0f);
      m.ior = index_of_refraction(ps);
      m.roughness = roughness(d, ps, m);
    } else if (type == "thindielectric") {
      m.type = MaterialType::ThinDielectric;  // pbrt-v4's ThinDielectricBxDF: smooth only
      m.albedo = Vec3(1.0f);
      m.ior = index_of_refraction(ps);
    } else if (type == "mix") {
      // pbrt-v4's MixMaterial: two named materials, defined before, and the probability of the
      // second (amount <= 0 and >= 1 choose one outright, as pbrt-v4 does).
      m.type = MaterialType::Mix;
      const PbrtParam* p = ps.find("materials");
      if (!p || pbrt_canonical_type(p->type) != "string" || p->strings.size() != 2)
        fail(p ? p->at : d.at, "a \"mix\" material needs \"string materials\" with two named materials");
      p->used = true;
      for (size_t i = 0; i < 2; ++i) {
        auto it = named_materials_.find(p->strings[i]);
        if (it == named_materials_.end()) fail(p->at, "unknown named material \"" + p->strings[i] + "\" in \"materials\"");
        if (it->second == -2) fail(p->at, "a mix of \"" + p->strings[i] + "\" (an interface, no surface) is not supported");
        m.mix[i] = it->second;
      }
      if (const PbrtParam* a = ps.find("amount"); a && pbrt_canonical_type(a->type) == "texture") {
        a->used = true;
        if (auto t = texture_ref(*a, "float")) m.textures.push_back({MaterialParam::Amount, *t});
      } else if (std::optional<double> v = ps.find_float("amount")) {
        if (!std::isfinite(*v)) fail(ps.find("amount")->at, "\"float amount\" must be finite");
        m.amount = float(std::clamp(*v, 0.0, 1.0));
      }
    } else {
      note(d.at, "material \"" + type + "\" is not supported (diffuse 0.5 used)");
      for (const PbrtParam& p : ps.list) p.used = true;
      m.type = MaterialType::Diffuse;
      m.albedo = Vec3(0.5f);
    }
    out_.scene.materials.push_back(m);
    return int(out_.scene.materials.size()) - 1;
  }

  // A conductor's eta or k: rgb, or pbrt-v4's named metal spectra for the metals pdrt has.
  Vec3 metal_param(const PbrtParams& ps, const std::string& name, bool eta) {
    const PbrtParam* p = ps.find(name);
    const NamedMetal* cu = find_named_metal("Cu");  // pbrt-v4's default conductor is copper
    if (!p) return eta ? cu->eta : cu->k;
    p->used = true;
    if (pbrt_canonical_type(p->type) == "spectrum" && !p->strings.empty()) {
      const std::string& s = p->strings[0];
      for (const char* metal : {"Au", "Ag", "Cu", "Al"})
        if (s == std::string("metal-") + metal + (eta ? "-eta" : "-k")) return eta ? find_named_metal(metal)->eta : find_named_metal(metal)->k;
      note(p->at, "named spectrum \"" + s + "\" is not supported (copper used)");
      return eta ? cu->eta : cu->k;
    }
    if (pbrt_canonical_type(p->type) == "float" && p->numbers.size() == 1) return Vec3(float(p->numbers[0]));
    p->used = false;
    return color(ps, name, eta ? cu->eta : cu->k, false);
  }

  // pbrt-v4's named glasses at the sodium d line (587.6 nm): pdrt's dielectric takes one index.
  // "eta" of a dielectric or a coat: a number (default 1.5), a named glass or a spectrum.
  float index_of_refraction(const PbrtParams& ps) {
    const PbrtParam* e = ps.find("eta");
    if (!e || pbrt_canonical_type(e->type) != "spectrum") return positive(ps, "eta", 1.5f);
    e->used = true;
    return named_glass_ior(*e);
  }

  float named_glass_ior(const PbrtParam& p) {
    static const std::map<std::string, float> kGlass = {{"glass-BK7", 1.5168f}, {"glass-BAF10", 1.6700f},
                                                        {"glass-FK51A", 1.4866f}, {"glass-LASF9", 1.8503f},
                                                        {"glass-F5", 1.6034f}, {"glass-F10", 1.6200f},
                                                        {"glass-F11", 1.6209f}};
    if (!p.strings.empty()) {
      auto it = kGlass.find(p.strings[0]);
      if (it != kGlass.end()) return it->second;
      note(p.at, "named spectrum \"" + p.strings[0] + "\" is not supported (1.5 used)");
      return 1.5f;
    }
    note(p.at, "a spectrally varying index is not supported (its value nearest 550 nm used)");
    double best = 1.5, dist = 1e30;
    for (size_t i = 0; i + 1 < p.numbers.size(); i += 2)
      if (std::abs(p.numbers[i] - 550) < dist) dist = std::abs(p.numbers[i] - 550), best = p.numbers[i + 1];
    if (!(best > 0)) fail(p.at, "the index of refraction must be > 0");
    return float(best);
  }

  int current_material() {
    if (cur_.material >= 0) return cur_.material;
    if (default_material_ < 0) {
      Material m;
      m.name = "pbrt default";
      m.type = MaterialType::Diffuse;
      m.albedo = Vec3(0.5f);
      out_.scene.materials.push_back(m);
      default_material_ = int(out_.scene.materials.size()) - 1;
    }
    return default_material_;
  }

  void light(const PbrtDirective& d) {
    const PbrtParams& ps = d.params;
    const std::string& t = d.strings[0];
    const float scale = float(ps.get_float("scale", 1));
    if (!(scale >= 0) || !std::isfinite(scale)) fail(d.at, "\"float scale\" must be >= 0");
    if (t == "point" || t == "spot") {
      DeltaLightDesc l;
      l.kind = t == "point" ? DeltaLightDesc::Kind::Point : DeltaLightDesc::Kind::Spot;
      Vec3 I = color(ps, "I", Vec3(1.0f), true) * scale;
      std::vector<Vec3> from = ps.point3s("from");
      l.position = from.empty() ? Vec3(0.0f) : from[0];
      if (t == "spot") {
        std::vector<Vec3> to = ps.point3s("to");
        const Vec3 target = to.empty() ? Vec3(0, 0, 1) : to[0];
        if (length(target - l.position) == 0) fail(d.at, "a spot light needs \"to\" different from \"from\"");
        l.direction = normalize(target - l.position);
        const double cone = ps.get_float("coneangle", 30), delta = ps.get_float("conedeltaangle", 5);
        if (!(cone > 0 && cone <= 180)) fail(d.at, "\"float coneangle\" must be in (0, 180], got " + fmt(cone));
        l.cos_cone = float(std::cos(cone * kPiD / 180));
        l.cos_falloff_start = float(std::cos(std::clamp(cone - delta, 0.0, cone) * kPiD / 180));
      }
      if (auto power = ps.find_float("power")) {
        // pbrt-v4: the intensity that radiates `power` watts (4 pi I for a point light; a spot
        // light's cone integral), by luminance.
        const double solid = t == "point" ? 4 * kPiD : 2 * kPiD * (1 - 0.5 * (l.cos_cone + l.cos_falloff_start));
        const double lum = luminance(I);
        if (lum > 0) I = I * float(*power / (solid * lum));
      }
      l.intensity = I;
      place(d.at, &l.transform, &l.motion);
      out_.scene.delta_lights.push_back(l);
      return;
    }
    if (t == "distant") {
      DeltaLightDesc l;
      l.kind = DeltaLightDesc::Kind::Distant;
      Vec3 L = color(ps, "L", Vec3(1.0f), true) * scale;
      std::vector<Vec3> from = ps.point3s("from"), to = ps.point3s("to");
      const Vec3 f = from.empty() ? Vec3(0.0f) : from[0], g = to.empty() ? Vec3(0, 0, 1) : to[0];
      if (length(g - f) == 0) fail(d.at, "a distant light needs \"to\" different from \"from\"");
      if (moving()) note(d.at, "a moving distant light is not supported (its start direction is used)");
      if (!cur_.ctm.t[0].affine()) fail(d.at, "the current transform is projective");
      const Vec3 travel = cur_.ctm.t[0].vector(g - f);
      if (!(length(travel) > 0)) fail(d.at, "the current transform collapses the light's direction");
      l.direction = normalize(travel);
      if (auto e = ps.find_float("illuminance")) {
        const double lum = luminance(L);
        if (lum > 0) L = L * float(*e / lum);
      }
      l.irradiance = L;
      out_.scene.delta_lights.push_back(l);
      return;
    }
    if (t == "infinite") {
      if (!is_black(out_.scene.environment.radiance) || out_.scene.environment.has_map()) {
        note(d.at, "a second infinite light is not supported (skipped)");
        for (const PbrtParam& p : ps.list) p.used = true;
        return;
      }
      if (ps.find("filename")) return image_light(d, scale);
      Vec3 L = color(ps, "L", Vec3(1.0f), true) * scale;
      if (auto e = ps.find_float("illuminance")) {
        // Illuminance of the upper hemisphere: pi L (by luminance).
        const double lum = luminance(L);
        if (lum > 0) L = L * float(*e / (kPiD * lum));
      }
      out_.scene.environment.radiance = L;
      return;
    }
    note(d.at, "LightSource \"" + t + "\" is not supported (skipped)");
    for (const PbrtParam& p : ps.list) p.used = true;
  }

  // An infinite light with an image: pbrt-v4's equal-area octahedral square, resampled into
  // pdrt's equirectangular environment (equal_area_octahedral.h).
  void image_light(const PbrtDirective& d, float scale) {
    const PbrtParams& ps = d.params;
    const PbrtParam& f = *ps.find("filename");
    const std::string name = *ps.find_string("filename");
    if (ps.find("L")) fail(ps.find("L")->at, "an infinite light takes \"L\" or \"filename\", not both");
    const std::filesystem::path rel = d.at.file ? std::filesystem::path(*d.at.file).parent_path() : std::filesystem::path();
    const std::filesystem::path file = std::filesystem::path(name).is_absolute() ? std::filesystem::path(name) : rel / name;
    EnvironmentImage img;
    std::string reason;
    if (!read_environment_image(file, &img, &reason)) fail(f.at, "cannot read \"" + name + "\": " + reason);
    if (img.width != img.height)
      fail(f.at, "\"" + name + "\" is " + std::to_string(img.width) + " x " + std::to_string(img.height) +
                     ": pbrt-v4's environment images are square (equal-area octahedral)");
    for (float v : img.rgb)
      if (!(std::isfinite(v) && v >= 0)) fail(f.at, "\"" + name + "\" holds a negative or non-finite value");
    if (!cur_.ctm.t[0].affine()) fail(d.at, "the current transform is projective");
    if (moving()) note(d.at, "a moving infinite light is not supported (its start orientation is used)");
    const std::optional<Mat4> inv = cur_.ctm.t[0].inverse();
    if (!inv) fail(d.at, "the current transform is singular");
    double e_v = 0;
    if (auto e = ps.find_float("illuminance")) {
      // pbrt-v4: scale so the upper hemisphere (light space +z) gives illuminance e; every
      // texel of the equal-area square subtends 4 pi / n^2.
      double sum = 0;
      const int n = img.width;
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const Vec3 w = equal_area_square_to_sphere((x + 0.5) / n, (y + 0.5) / n);
          const float* p = &img.rgb[3 * (size_t(y) * size_t(n) + size_t(x))];
          if (w.z > 0) sum += luminance(Vec3(p[0], p[1], p[2])) * w.z;
        }
      e_v = sum * 4 * kPiD / (double(n) * n);
      if (e_v > 0) scale *= float(*e / e_v);
    }
    const Mat4 to_light = *inv;
    EnvironmentImage eq = octahedral_to_equirect(img, [&](const Vec3& w) { return to_light.vector(w); });
    EnvironmentDesc& env = out_.scene.environment;
    env.file = file.string();
    env.width = eq.width, env.height = eq.height;
    env.rgb = std::move(eq.rgb);
    env.scale = Vec3(scale);
    env.resampled = true;
  }

  void shape(const PbrtDirective& d) {
    const PbrtParams& ps = d.params;
    const std::string& t = d.strings[0];
    if (cur_.interface) {
      for (const PbrtParam& p : ps.list) p.used = true;
      return;  // an interface bounds media only: nothing to see
    }
    if (const PbrtParam* p = ps.find("alpha")) {
      p->used = true;
      note(p->at, "\"alpha\" cut-outs are not supported (the shape is opaque)");
    }
    ShapeDesc s;
    s.where = d.at.str();
    const bool flip = cur_.reverse != (cur_.ctm.t[0].det3() < 0);
    if (t == "sphere") {
      s.kind = ShapeDesc::Kind::Sphere;
      s.radius = positive(ps, "radius", 1);
      const double zmin = ps.get_float("zmin", -s.radius), zmax = ps.get_float("zmax", s.radius), phimax = ps.get_float("phimax", 360);
      if (zmin > -s.radius || zmax < s.radius || phimax < 360) note(d.at, "partial spheres are not supported (the whole sphere is used)");
      if (flip && cur_.area) note(d.at, "an inward-facing emitting sphere is not supported (it emits outward)");
    } else if (t == "trianglemesh" || t == "loopsubdiv" || t == "bilinearmesh" || t == "plymesh") {
      std::vector<Vec3> P, N;
      std::vector<std::array<float, 2>> uvs;
      std::vector<int64_t> idx;
      if (t == "plymesh") {
        std::optional<std::string> name = ps.find_string("filename");
        if (!name) fail(d.at, "Shape \"plymesh\" needs \"string filename\"");
        const std::filesystem::path rel = d.at.file ? std::filesystem::path(*d.at.file).parent_path() : std::filesystem::path();
        const std::filesystem::path file = std::filesystem::path(*name).is_absolute() ? std::filesystem::path(*name) : rel / *name;
        PlyMesh ply;
        try {
          ply = load_ply(file, file.string());
        } catch (const InputError& e) {
          fail(ps.find("filename")->at, e.what());
        }
        if (ply.dropped_faces) note(ps.find("filename")->at, std::to_string(ply.dropped_faces) + " points or lines in the PLY file are not surfaces (skipped)");
        P = std::move(ply.mesh.positions);
        N = std::move(ply.mesh.normals);
        uvs = std::move(ply.uvs);
        idx.assign(ply.mesh.indices.begin(), ply.mesh.indices.end());
        for (const char* k : {"displacement", "edgelength"})
          if (const PbrtParam* p = ps.find(k)) {
            p->used = true;
            note(p->at, std::string("\"") + k + "\" is not supported (ignored)");
          }
      } else {
        P = ps.point3s("P");
        idx = ps.ints("indices");
        if (t != "loopsubdiv") N = ps.normal3s("N");
      }
      if (P.empty()) fail(d.at, "Shape \"" + t + "\" needs \"point3 P\"");
      if (t == "trianglemesh" && idx.empty()) {
        if (P.size() != 3) fail(d.at, "a trianglemesh without \"indices\" must have exactly 3 points, got " + std::to_string(P.size()));
        idx = {0, 1, 2};
      }
      if (t == "bilinearmesh") {
        if (idx.empty() && P.size() == 4) idx = {0, 1, 2, 3};
        if (idx.size() % 4) fail(d.at, "\"integer indices\" of a bilinearmesh needs a multiple of 4 values");
        std::vector<int64_t> tri;
        for (size_t i = 0; i < idx.size(); i += 4) {
          // Vertices p00 p10 p01 p11: two triangles (exact for planar patches).
          tri.insert(tri.end(), {idx[i], idx[i + 1], idx[i + 3], idx[i], idx[i + 3], idx[i + 2]});
        }
        idx = tri;
        note(d.at, "bilinear patches are split into two triangles each (exact only where they are planar)");
      }
      if (idx.size() % 3) fail(d.at, "\"integer indices\" needs a multiple of 3 values, got " + std::to_string(idx.size()));
      for (int64_t i : idx)
        if (i < 0 || uint64_t(i) >= P.size())
          fail(ps.find("indices") ? ps.find("indices")->at : d.at, "index " + std::to_string(i) + " is out of range [0, " + std::to_string(P.size() - 1) + "]");
      for (const Vec3& p : P)
        if (!is_finite(p)) fail(ps.find("P") ? ps.find("P")->at : d.at, "\"P\" holds a non-finite coordinate");
      if (t == "loopsubdiv") {
        const int64_t levels = ps.get_int("levels", 3);
        if (levels < 0 || levels > 12) fail(ps.find("levels")->at, "\"integer levels\" must be in [0, 12], got " + std::to_string(levels));
        MeshData m;
        try {
          m = loop_subdivide(P, std::vector<uint32_t>(idx.begin(), idx.end()), int(levels));
        } catch (const InputError& e) {
          fail(d.at, std::string("Shape \"loopsubdiv\": ") + e.what());
        }
        P = std::move(m.positions), N = std::move(m.normals);
        idx.assign(m.indices.begin(), m.indices.end());
      }
      const PbrtLocation n_at = ps.find("N") ? ps.find("N")->at : d.at;
      if (!N.empty() && N.size() != P.size())
        fail(n_at, "\"N\" needs one normal per point (" + std::to_string(P.size()) + "), got " + std::to_string(N.size()));
      for (Vec3& n : N)
        if (!(length(n) > 0) || !is_finite(n)) fail(n_at, "\"N\" holds a zero or non-finite normal");
      if (t != "plymesh" && t != "loopsubdiv") uvs = ps.point2s("uv");
      if (!uvs.empty() && uvs.size() != P.size())
        fail(ps.find("uv") ? ps.find("uv")->at : d.at, "\"uv\" needs one per point (" + std::to_string(P.size()) + "), got " + std::to_string(uvs.size()));
      for (const char* k : {"S", "faceIndices"})
        if (const PbrtParam* p = ps.find(k)) p->used = true;
      s.mesh.positions = std::move(P);
      s.mesh.normals = std::move(N);
      s.mesh.uvs = std::move(uvs);
      s.mesh.indices.reserve(idx.size());
      const bool swaps = cur_.ctm.t[0].det3() < 0;
      for (size_t i = 0; i < idx.size(); i += 3) {
        uint32_t a = uint32_t(idx[i]), b = uint32_t(idx[i + 1]), c = uint32_t(idx[i + 2]);
        const Vec3 &pa = s.mesh.positions[a], &pb = s.mesh.positions[b], &pc = s.mesh.positions[c];
        const Vec3 ng = cross(pb - pa, pc - pa);
        if (!(length(ng) > 0)) continue;  // degenerate
        // pbrt's geometric normal follows the shading normals when there are some, else the
        // winding, reversed by ReverseOrientation and by a handedness-swapping transform.
        bool swap = flip;
        if (!s.mesh.normals.empty()) swap = (dot(ng, s.mesh.normals[a] + s.mesh.normals[b] + s.mesh.normals[c]) < 0) != swaps;
        if (swap) std::swap(b, c);
        s.mesh.indices.insert(s.mesh.indices.end(), {a, b, c});
      }
      if (s.mesh.indices.empty()) {
        note(d.at, "the mesh has only degenerate triangles (skipped)");
        return;
      }
    } else if (t == "disk") {
      const double h = ps.get_float("height", 0), r = positive(ps, "radius", 1), ri = positive(ps, "innerradius", 0, true);
      if (ps.get_float("phimax", 360) < 360) note(d.at, "partial disks are not supported (the whole disk is used)");
      if (!(ri < r)) fail(d.at, "\"innerradius\" must be < \"radius\"");
      // A fan (or ring) of 256 triangles; the polygon's area is 0.01 % below the disk's.
      const int n = 256;
      for (int i = 0; i < n; ++i) {
        const double phi = 2 * kPiD * i / n;
        s.mesh.positions.push_back({float(r * std::cos(phi)), float(r * std::sin(phi)), float(h)});
        if (ri > 0) s.mesh.positions.push_back({float(ri * std::cos(phi)), float(ri * std::sin(phi)), float(h)});
      }
      if (ri == 0) s.mesh.positions.push_back({0, 0, float(h)});
      for (uint32_t i = 0; i < uint32_t(n); ++i) {
        const uint32_t j = (i + 1) % n;
        // Counter-clockwise seen from +z: pbrt's disk faces +z.
        if (ri == 0) {
          s.mesh.indices.insert(s.mesh.indices.end(), {uint32_t(n), i, j});
        } else {
          s.mesh.indices.insert(s.mesh.indices.end(), {2 * i + 1, 2 * i, 2 * j, 2 * i + 1, 2 * j, 2 * j + 1});
        }
      }
      if (flip)
        for (size_t i = 0; i < s.mesh.indices.size(); i += 3) std::swap(s.mesh.indices[i + 1], s.mesh.indices[i + 2]);
    } else {
      note(d.at, "Shape \"" + t + "\" is not supported (skipped)");
      for (const PbrtParam& p : ps.list) p.used = true;
      return;
    }
    if (cur_.area && !object_) {
      Material m;
      m.name = "area light at " + cur_.area->at.str();
      m.type = MaterialType::Emitter;
      m.radiance = cur_.area->radiance;
      m.two_sided = cur_.area->two_sided;
      out_.scene.materials.push_back(m);
      s.material = int(out_.scene.materials.size()) - 1;
    } else {
      if (cur_.area && object_) note(d.at, "area lights inside object definitions are not supported (no emission)");
      s.material = current_material();
    }
    if (object_) {
      // pbrt-v4 keeps the whole CTM at the shape's definition (the CTM at ObjectBegin
      // included) as the shape's transform within the object; instances apply theirs on top.
      if (!cur_.ctm.t[0].affine()) fail(d.at, "the current transform is projective; shapes and lights need an affine one");
      if (moving()) note(d.at, "a moving shape inside an object definition is not supported (its start transform is used)");
      s.transform = cur_.ctm.t[0].to_affine();
      s.where = d.at.str();
      out_.scene.prototypes[size_t(objects_[*object_])].shapes.push_back(std::move(s));
      return;
    }
    place(d.at, &s.transform, &s.motion);
    if (!s.motion.empty() && !(times_[0] >= out_.scene.camera.shutter_open && times_[1] <= out_.scene.camera.shutter_close)) {
      note(d.at, "motion keys at TransformTimes outside the camera's shutter (the shape's motion is clamped to the shutter)");
    }
    out_.scene.shapes.push_back(std::move(s));
  }

  bool strict_;
  PbrtImport out_;
  Attributes cur_;
  std::vector<std::pair<PbrtLocation, Attributes>> attr_stack_;
  std::vector<bool> attr_kind_;  // true: TransformBegin
  std::map<std::string, TransformPair> named_;
  std::map<std::string, int> named_materials_;
  std::map<std::string, int> objects_;  // object name -> index in out_.scene.prototypes
  std::optional<std::string> object_;
  PbrtLocation object_at_, camera_at_;
  std::optional<PbrtLocation> last_;
  double times_[2] = {0, 1};
  bool in_world_ = false, camera_seen_ = false;
  float fov_ = 90;
  std::optional<std::array<float, 4>> screen_window_;  // pbrt's, in screen space
  std::optional<float> frame_aspect_;
  std::array<float, 2> camera_scale_{1, 1};  // camera space's x and y unit in scene units
  int default_material_ = -1;
  std::vector<long long> texture_cost_;  // per scene texture: texture_node_cost
  std::map<std::string, int> textures_;  // "float:name" / "spectrum:name" -> index, -1 unsupported
  std::vector<TextureBinding>* bind_to_ = nullptr;  // where color() binds a texture parameter
  MaterialParam bind_param_ = MaterialParam::Albedo;

 public:
  float fov() const { return fov_; }

  // pbrt-v4 CameraBase: the screen window defaults to [-frame, frame] x [-1, 1] when the
  // frame aspect ratio (default the film's) is above 1, else [-1, 1] x [-1/frame, 1/frame].
  // pdrt's window is on the plane at distance 1 (perspective: pbrt's screen space is that
  // scaled by 1/tan(fov/2)) or in scene units (orthographic). Without either parameter the
  // default needs no window: pdrt's vfov (build_pbrt_scene) or ortho_height covers it.
  void resolve_screen(SceneDesc& s) const {
    CameraDesc& c = s.camera;
    const bool ortho = c.projection == CameraDesc::Projection::Orthographic;
    const float sx = camera_scale_[0], sy = camera_scale_[1];
    if (!screen_window_ && !frame_aspect_) {
      if (ortho && std::abs(sx - sy) <= 1e-6f * sy) c.ortho_height = (s.film.width >= s.film.height ? 2.0f : 2.0f * float(s.film.height) / float(s.film.width)) * sy;
      if (!ortho || std::abs(sx - sy) <= 1e-6f * sy) return;
    }
    const float frame = frame_aspect_.value_or(float(s.film.width) / float(s.film.height));
    std::array<float, 4> w = frame > 1 ? std::array<float, 4>{-frame, frame, -1, 1} : std::array<float, 4>{-1, 1, -1 / frame, 1 / frame};
    if (screen_window_) w = *screen_window_;
    const float kx = ortho ? sx : float(std::tan(0.5 * fov_ * kPiD / 180)), ky = ortho ? sy : kx;
    c.screen_window = {w[0] * kx, w[1] * kx, w[2] * ky, w[3] * ky};
    c.has_screen_window = true;
  }
};

}  // namespace

PbrtImport build_pbrt_scene(const std::vector<PbrtDirective>& directives, bool strict) {
  Builder b(strict);
  PbrtImport out = b.run(directives);
  b.resolve_screen(out.scene);
  // pbrt's sphere has its pole on +z and its azimuth from +x toward +y; pdrt's has the pole on
  // +y and the azimuth from +x toward +z. Swapping y and z in object space (a mirror, harmless
  // to a sphere) gives every texel the direction pbrt gives it.
  Affine swap_yz;
  swap_yz.m = {{{1, 0, 0, 0}, {0, 0, 1, 0}, {0, 1, 0, 0}}};
  for (ShapeDesc& s : out.scene.shapes)
    if (s.kind == ShapeDesc::Kind::Sphere) s.transform = s.transform * swap_yz;
  for (PrototypeDesc& p : out.scene.prototypes)
    for (ShapeDesc& s : p.shapes)
      if (s.kind == ShapeDesc::Kind::Sphere) s.transform = s.transform * swap_yz;
  // pbrt's fov spans the film's shorter side; pdrt's is vertical.
  FilmDesc& f = out.scene.film;
  const double half = std::tan(0.5 * b.fov() * kPiD / 180);
  out.scene.camera.vfov_deg =
      f.width >= f.height ? b.fov() : float(2 * std::atan(half * double(f.height) / f.width) * 180 / kPiD);
  return out;
}

PbrtImport load_pbrt_scene(const std::filesystem::path& file, bool strict) {
  PbrtImport out = build_pbrt_scene(parse_pbrt_file(file), strict);
  out.scene.file = file;
  return out;
}

}  // namespace pdrt
