#pragma once
// Parses pbrt-v4 scene files into a flat list of typed directives, each with its kind, its fixed
// arguments and its parameter list, `Include` and `Import` expanded in place (paths relative to the file that
// names them; a file that includes itself, directly or not, is refused). The directives' meaning
// (transforms, graphics state, the mapping to pdrt's scene) is pbrt_scene_builder's business,
// which switches on the kind;
// this layer only checks the grammar: known directive names, the number and kind of their
// arguments, well-formed "type name" declarations and values of the declared type.
#include "renderer/scene/pbrt/pbrt_parameters.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace pdrt {

// Every directive pbrt-v4's file format has, in the order of its documentation's sections.
enum class PbrtDirectiveKind {
  // transforms
  Identity,
  Translate,
  Scale,
  Rotate,
  LookAt,
  Transform,
  ConcatTransform,
  CoordinateSystem,
  CoordSysTransform,
  ActiveTransform,
  TransformTimes,
  ReverseOrientation,
  // block structure and graphics state
  WorldBegin,
  WorldEnd,
  AttributeBegin,
  AttributeEnd,
  TransformBegin,
  TransformEnd,
  Attribute,
  ObjectBegin,
  ObjectEnd,
  ObjectInstance,
  // rendering options
  Camera,
  Film,
  PixelFilter,
  Sampler,
  Integrator,
  Accelerator,
  ColorSpace,
  Option,
  // scene elements
  Texture,
  Material,
  MakeNamedMaterial,
  NamedMaterial,
  LightSource,
  AreaLightSource,
  Shape,
  MakeNamedMedium,
  MediumInterface,
  // files (expanded by the parser, never in its output)
  Include,
  Import,
};

struct PbrtDirective {
  std::string name;  // "Shape", "Translate", ... as written
  PbrtDirectiveKind kind = PbrtDirectiveKind::Identity;
  PbrtLocation at;                   // of the directive's name
  std::vector<double> numbers;       // numeric arguments: Translate 3, Rotate 4, LookAt 9, Transform 16, ...
  std::vector<std::string> strings;  // string arguments: the type of Shape/Material/..., names, files
  PbrtParams params;
};

// Throws InputError "file:line:col: ..." on the first problem (an unreadable file names the
// Include that asked for it).
std::vector<PbrtDirective> parse_pbrt_file(const std::filesystem::path& file);

// The same for text in memory; `name` is the file name messages print and `dir` the directory
// Include paths resolve against.
std::vector<PbrtDirective> parse_pbrt_text(std::string_view text, const std::string& name,
                                           const std::filesystem::path& dir);

}  // namespace pdrt
