#pragma once
// pbrt-v4's graphics state, as its BasicSceneBuilder keeps it: the current transform at the
// shutter's start and end (ActiveTransform, TransformTimes), reverse orientation, the current
// material and area light, the Attribute defaults, the AttributeBegin/TransformBegin stack,
// named coordinate systems, named materials and the object being defined. The transform and
// block directives change it here; what the scene builds from it is the translators' business
// (pbrt_build_context.h).
#include "renderer/scene/pbrt/pbrt_matrix.h"
#include "renderer/scene/pbrt/pbrt_parser.h"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pdrt {

struct PbrtTransformPair {
  Mat4 t[2];  // at the shutter's start and end (TransformTimes)
};

struct PbrtAreaLight {
  Vec3 radiance;
  bool two_sided = false;
  std::optional<double> power;  // pbrt-v4: radiance x power / (sides x pi x the shape's area)
  PbrtLocation at;
};

struct PbrtAttributes {
  PbrtTransformPair ctm;
  bool active[2] = {true, true};
  bool reverse = false;
  int material = -1;       // index into the scene's materials; -1 = pbrt's default (diffuse 0.5)
  bool interface = false;  // the current material is "interface": shapes bound no surface
  std::optional<PbrtAreaLight> area;
  // Attribute "shape" | "light" | "material" | "texture": parameters every later directive of
  // that kind takes unless it sets them itself (pbrt-v4 file format, "Attributes").
  std::map<std::string, std::vector<PbrtParam>> defaults;
};

class PbrtGraphicsState {
 public:
  PbrtAttributes cur;
  std::vector<std::pair<PbrtLocation, PbrtAttributes>> stack;  // AttributeBegin, TransformBegin, ObjectBegin
  std::vector<bool> stack_transform_only;                      // per entry: TransformBegin
  std::map<std::string, PbrtTransformPair> named;              // CoordinateSystem
  std::map<std::string, int> named_materials;                  // -> scene material, -2 interface
  std::map<std::string, int> objects;                          // object name -> index in prototypes
  std::optional<std::string> object;                           // being defined
  PbrtLocation object_at;
  double times[2] = {0, 1};
  bool in_world = false;

  // Identity, Translate, Scale, Rotate, LookAt, Transform, ConcatTransform, CoordinateSystem,
  // CoordSysTransform, ActiveTransform, TransformTimes, ReverseOrientation, AttributeBegin/End,
  // TransformBegin/End. Throws InputError "file:line:col: ..." for a bad one.
  void transform_directive(const PbrtDirective& d);

  // The Attribute defaults the directive reads, or nullptr.
  const std::vector<PbrtParam>* defaults_for(PbrtDirectiveKind kind) const;
  // Attribute "shape" | "light" | "material" | "texture": a later value replaces an earlier one.
  void set_defaults(const std::string& target, const std::vector<PbrtParam>& params);

  // ObjectBegin keeps the attributes (and refuses nesting and a second definition); ObjectEnd
  // restores them.
  void begin_object(const PbrtDirective& d);
  void end_object(const PbrtDirective& d);
  void begin_world();

  bool moving() const { return !(cur.ctm.t[0] == cur.ctm.t[1]); }

 private:
  void apply(const Mat4& m);
  void set(const Mat4& m);
  void begin(const PbrtDirective& d);
  void end(const PbrtDirective& d);
};

}  // namespace pdrt
