#pragma once
// Parses pbrt-v4 scene files into a flat list of directives, each with its fixed arguments and
// its parameter list, `Include` and `Import` expanded in place (paths relative to the file that
// names them; a file that includes itself, directly or not, is refused). The directives' meaning
// (transforms, graphics state, the mapping to pdrt's scene) is pbrt_scene_builder's business;
// this layer only checks the grammar: known directive names, the number and kind of their
// arguments, well-formed "type name" declarations and values of the declared type.
#include "renderer/scene/pbrt/pbrt_parameters.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace pdrt {

struct PbrtDirective {
  std::string name;                  // "Shape", "Translate", ...
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
