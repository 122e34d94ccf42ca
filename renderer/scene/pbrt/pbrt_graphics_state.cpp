#include "renderer/scene/pbrt/pbrt_graphics_state.h"

#include "sampling/core/errors.h"

#include <algorithm>

namespace pdrt {
namespace {

[[noreturn]] void fail(const PbrtLocation& at, const std::string& what) { throw InputError(at.str() + ": " + what); }

// The Attribute target a directive reads its defaults from ("" = none).
const char* attribute_target(PbrtDirectiveKind kind) {
  switch (kind) {
    case PbrtDirectiveKind::Shape:
      return "shape";
    case PbrtDirectiveKind::LightSource:
    case PbrtDirectiveKind::AreaLightSource:
      return "light";
    case PbrtDirectiveKind::Material:
    case PbrtDirectiveKind::MakeNamedMaterial:
      return "material";
    case PbrtDirectiveKind::Texture:
      return "texture";
    default:
      return "";
  }
}

}  // namespace

void PbrtGraphicsState::apply(const Mat4& m) {
  for (int i = 0; i < 2; ++i)
    if (cur.active[i]) cur.ctm.t[i] = cur.ctm.t[i] * m;
}

void PbrtGraphicsState::set(const Mat4& m) {
  for (int i = 0; i < 2; ++i)
    if (cur.active[i]) cur.ctm.t[i] = m;
}

void PbrtGraphicsState::transform_directive(const PbrtDirective& d) {
  const auto& a = d.numbers;
  switch (d.kind) {
    case PbrtDirectiveKind::Identity:
      return set(Mat4{});
    case PbrtDirectiveKind::Translate:
      return apply(Mat4::translate(a[0], a[1], a[2]));
    case PbrtDirectiveKind::Scale:
      return apply(Mat4::scale(a[0], a[1], a[2]));
    case PbrtDirectiveKind::Rotate:
      if (a[1] == 0 && a[2] == 0 && a[3] == 0) fail(d.at, "Rotate needs a non-zero axis");
      return apply(Mat4::rotate(a[0], a[1], a[2], a[3]));
    case PbrtDirectiveKind::LookAt: {
      auto m = Mat4::look_at({float(a[0]), float(a[1]), float(a[2])}, {float(a[3]), float(a[4]), float(a[5])},
                             {float(a[6]), float(a[7]), float(a[8])});
      if (!m) fail(d.at, "LookAt needs distinct eye and look points and an up vector not along the view");
      return apply(*m);
    }
    case PbrtDirectiveKind::Transform:
      return set(Mat4::from_pbrt(a.data()));
    case PbrtDirectiveKind::ConcatTransform:
      return apply(Mat4::from_pbrt(a.data()));
    case PbrtDirectiveKind::CoordinateSystem:
      named[d.strings[0]] = cur.ctm;
      return;
    case PbrtDirectiveKind::CoordSysTransform: {
      auto it = named.find(d.strings[0]);
      if (it == named.end()) fail(d.at, "unknown coordinate system \"" + d.strings[0] + "\"");
      for (int i = 0; i < 2; ++i)
        if (cur.active[i]) cur.ctm.t[i] = it->second.t[i];
      return;
    }
    case PbrtDirectiveKind::ActiveTransform:
      cur.active[0] = d.strings[0] != "EndTime";
      cur.active[1] = d.strings[0] != "StartTime";
      return;
    case PbrtDirectiveKind::TransformTimes:
      if (in_world) fail(d.at, "TransformTimes must come before WorldBegin");
      if (!(a[0] <= a[1]))
        fail(d.at, "TransformTimes needs start <= end, got " + pbrt_number(a[0]) + " > " + pbrt_number(a[1]));
      times[0] = a[0], times[1] = a[1];
      return;
    case PbrtDirectiveKind::ReverseOrientation:
      cur.reverse = !cur.reverse;
      return;
    case PbrtDirectiveKind::AttributeBegin:
    case PbrtDirectiveKind::TransformBegin:
      return begin(d);
    case PbrtDirectiveKind::AttributeEnd:
    case PbrtDirectiveKind::TransformEnd:
      return end(d);
    default:
      fail(d.at, "directive " + d.name + " is not a transform");
  }
}

void PbrtGraphicsState::begin(const PbrtDirective& d) {
  stack.push_back({d.at, cur});
  stack_transform_only.push_back(d.kind == PbrtDirectiveKind::TransformBegin);
}

void PbrtGraphicsState::end(const PbrtDirective& d) {
  const std::string& n = d.name;
  const bool closes_transform = d.kind == PbrtDirectiveKind::TransformEnd;
  if (stack.empty()) fail(d.at, n + " without a matching " + (!closes_transform ? "AttributeBegin" : "TransformBegin"));
  const bool transform_only = stack_transform_only.back();
  if (transform_only != closes_transform)
    fail(d.at, n + " closes the " + (transform_only ? "TransformBegin" : "AttributeBegin") + " at " +
                   stack.back().first.str());
  if (transform_only) {
    cur.ctm = stack.back().second.ctm;
    std::copy(stack.back().second.active, stack.back().second.active + 2, cur.active);
  } else {
    cur = stack.back().second;
  }
  stack.pop_back();
  stack_transform_only.pop_back();
}

const std::vector<PbrtParam>* PbrtGraphicsState::defaults_for(PbrtDirectiveKind kind) const {
  auto it = cur.defaults.find(attribute_target(kind));
  return it == cur.defaults.end() ? nullptr : &it->second;
}

void PbrtGraphicsState::set_defaults(const std::string& target, const std::vector<PbrtParam>& params) {
  std::vector<PbrtParam>& list = cur.defaults[target];
  for (const PbrtParam& p : params) {
    std::erase_if(list, [&](const PbrtParam& q) { return q.name == p.name; });
    list.push_back(p);
  }
}

void PbrtGraphicsState::begin_object(const PbrtDirective& d) {
  if (object) fail(d.at, "ObjectBegin inside the ObjectBegin at " + object_at.str());
  stack.push_back({d.at, cur});
  stack_transform_only.push_back(false);
  object = d.strings[0];
  object_at = d.at;
  if (objects.count(*object)) fail(d.at, "object \"" + *object + "\" is defined twice");
}

void PbrtGraphicsState::end_object(const PbrtDirective& d) {
  if (!object) fail(d.at, "ObjectEnd without ObjectBegin");
  object.reset();
  cur = stack.back().second;
  stack.pop_back();
  stack_transform_only.pop_back();
}

void PbrtGraphicsState::begin_world() {
  in_world = true;
  named["world"] = PbrtTransformPair{};
  cur.ctm = PbrtTransformPair{};
}

}  // namespace pdrt
