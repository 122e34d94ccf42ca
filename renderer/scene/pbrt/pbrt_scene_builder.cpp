#include "renderer/scene/pbrt/pbrt_scene_builder.h"

#include "renderer/scene/pbrt/pbrt_build_context.h"
#include "sampling/core/errors.h"

namespace pdrt {
namespace {

class Builder {
 public:
  Builder(bool strict, const PbrtLimits& limits) : b_(strict) { b_.limits = limits; }

  PbrtImport run(const std::vector<PbrtDirective>& ds) {
    apply_pbrt_defaults(b_.out.scene);
    for (const PbrtDirective& d : ds) {
      const std::vector<PbrtParam>* defaults = b_.gs.defaults_for(d.kind);
      if (!defaults) {
        directive(d);
        b_.report_unused(d.params.list);
        continue;
      }
      PbrtDirective with = d;
      for (const PbrtParam& p : *defaults)
        if (!d.params.has(p.name)) with.params.list.push_back(p);
      directive(with);
      // An attribute one directive does not read may be meant for another: only the
      // directive's own parameters are reported unused.
      b_.report_unused({with.params.list.begin(), with.params.list.begin() + long(d.params.list.size())});
    }
    finish_pbrt_camera(b_);
    if (!b_.gs.stack.empty()) b_.note(b_.gs.stack.back().first, "AttributeBegin is never closed (ignored)");
    drop_empty_prototypes();
    b_.finish_report();
    const SceneDesc& s = b_.out.scene;
    if (s.shapes.empty() && s.instances.empty() && s.delta_lights.empty() && is_black(s.environment.radiance) &&
        !s.environment.has_map())
      throw InputError((b_.last ? b_.last->str() : std::string("<pbrt>")) + ": the scene has no shapes and no lights");
    return std::move(b_.out);
  }

 private:
  // Objects without a shape pdrt renders have no instances (skipped with a note): they go, and
  // the instances' indices follow.
  void drop_empty_prototypes() {
    SceneDesc& s = b_.out.scene;
    std::vector<int> index(s.prototypes.size(), -1);
    std::vector<PrototypeDesc> kept;
    for (size_t i = 0; i < s.prototypes.size(); ++i)
      if (!s.prototypes[i].shapes.empty()) index[i] = int(kept.size()), kept.push_back(std::move(s.prototypes[i]));
    s.prototypes = std::move(kept);
    for (InstanceDesc& in : s.instances) in.prototype = index[size_t(in.prototype)];
  }

  // One directive, by kind: the graphics state changes here or in PbrtGraphicsState, the
  // scene's elements come from the translators (pbrt_build_context.h).
  void directive(const PbrtDirective& d) {
    using K = PbrtDirectiveKind;
    b_.last = d.at;
    switch (d.kind) {
      case K::Identity:
      case K::Translate:
      case K::Scale:
      case K::Rotate:
      case K::LookAt:
      case K::Transform:
      case K::ConcatTransform:
      case K::CoordinateSystem:
      case K::CoordSysTransform:
      case K::ActiveTransform:
      case K::TransformTimes:
      case K::ReverseOrientation:
      case K::AttributeBegin:
      case K::TransformBegin:
      case K::AttributeEnd:
      case K::TransformEnd:
        return b_.gs.transform_directive(d);
      case K::Camera:
      case K::Film:
      case K::PixelFilter:
      case K::Sampler:
      case K::Integrator:
        return translate_pbrt_option(b_, d);
      case K::Accelerator:
        return;  // pdrt always builds Embree's BVH; its parameters are reported unused
      case K::ColorSpace:
        if (d.strings[0] != "srgb")
          b_.note(d.at, "ColorSpace \"" + d.strings[0] + "\" is not supported (pdrt renders linear sRGB)");
        return;
      case K::Option:
        return;  // reported as unused parameters
      case K::WorldBegin:
        if (b_.gs.in_world) b_.fail(d.at, "a second WorldBegin");
        return b_.gs.begin_world();
      case K::WorldEnd:
        return;  // pbrt-v3
      case K::MakeNamedMedium:
      case K::MediumInterface:
        b_.note(d.at, d.name + " is not supported: pdrt has no participating media (ignored)");
        for (const PbrtParam& p : d.params.list) p.used = true;
        return;
      case K::Attribute:
        return attribute(d);
      case K::ObjectEnd:
        return b_.gs.end_object(d);
      case K::Texture:
        return translate_pbrt_texture(b_, d);
      default:
        break;
    }
    if (!b_.gs.in_world) b_.fail(d.at, d.name + " must come after WorldBegin");
    switch (d.kind) {
      case K::Material:
      case K::MakeNamedMaterial:
      case K::NamedMaterial:
        return translate_pbrt_material(b_, d);
      case K::AreaLightSource:
      case K::LightSource:
        return translate_pbrt_light(b_, d);
      case K::Shape:
        return translate_pbrt_shape(b_, d);
      case K::ObjectBegin:
        return object_begin(d);
      case K::ObjectInstance:
        return object_instance(d);
      default:
        b_.fail(d.at, "directive " + d.name + " is not handled");  // Include and Import are the parser's
    }
  }

  void attribute(const PbrtDirective& d) {
    const std::string& target = d.strings[0];
    if (target == "medium") {
      b_.note(d.at, "Attribute \"medium\" is not supported: pdrt has no participating media (ignored)");
    } else if (target != "shape" && target != "light" && target != "material" && target != "texture") {
      b_.fail(d.at, "Attribute target must be \"shape\", \"light\", \"material\", \"medium\" or \"texture\", got \"" +
                        target + "\"");
    } else {
      b_.gs.set_defaults(target, d.params.list);
    }
    for (const PbrtParam& p : d.params.list) p.used = true;
  }

  void object_begin(const PbrtDirective& d) {
    b_.gs.begin_object(d);
    // A prototype (SceneDesc::prototypes): its shapes are stored once, traced through Embree
    // instances.
    std::vector<PrototypeDesc>& prototypes = b_.out.scene.prototypes;
    b_.gs.objects[*b_.gs.object] = int(prototypes.size());
    PrototypeDesc proto;
    proto.name = *b_.gs.object;
    proto.where = d.at.str();
    prototypes.push_back(std::move(proto));
  }

  void object_instance(const PbrtDirective& d) {
    if (b_.gs.object) b_.fail(d.at, "ObjectInstance inside an object definition");
    auto it = b_.gs.objects.find(d.strings[0]);
    if (it == b_.gs.objects.end()) b_.fail(d.at, "unknown object \"" + d.strings[0] + "\"");
    if (b_.out.scene.prototypes[size_t(it->second)].shapes.empty()) {
      b_.note(d.at, "object \"" + d.strings[0] + "\" has no shapes pdrt can render (instance skipped)");
      return;
    }
    // pbrt-v4's BasicSceneBuilder::ObjectInstance: render-from-instance is the CTM here (at
    // the two TransformTimes when it moves), applied on top of the object's shapes' own CTMs.
    InstanceDesc inst;
    inst.prototype = it->second;
    b_.place(d.at, &inst.transform, &inst.motion);
    const double* times = b_.gs.times;
    const CameraDesc& c = b_.out.scene.camera;
    if (!inst.motion.empty() && !(times[0] >= c.shutter_open && times[1] <= c.shutter_close))
      b_.note(d.at,
              "motion keys at TransformTimes outside the camera's shutter (the instance's motion is clamped to the "
              "shutter)");
    inst.where = d.at.str();
    b_.out.scene.instances.push_back(std::move(inst));
  }

  PbrtBuild b_;
};

}  // namespace

PbrtImport build_pbrt_scene(const std::vector<PbrtDirective>& directives, bool strict, const PbrtLimits& limits) {
  PbrtImport out = Builder(strict, limits).run(directives);
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
  return out;
}

PbrtImport load_pbrt_scene(const std::filesystem::path& file, bool strict) {
  PbrtImport out = build_pbrt_scene(parse_pbrt_file(file), strict);
  out.scene.file = file;
  return out;
}

}  // namespace pdrt
