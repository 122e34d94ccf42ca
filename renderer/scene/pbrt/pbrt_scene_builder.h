#pragma once
// Turns pbrt-v4 directives (pbrt_parser.h) into pdrt's SceneDesc: a switch over each
// directive's kind hands it to the graphics state (pbrt_graphics_state.h: current transform at
// the shutter's start and end, attributes, named coordinate systems, materials, area lights,
// object instances, as pbrt-v4's BasicSceneBuilder keeps it) or to the translator of its kind
// (pbrt_build_context.h), which maps each camera, film, filter, sampler, integrator, texture,
// material, light and shape onto pdrt's (docs/pbrt-import.md). What pdrt cannot represent is listed in the report, one
// line each, "file:line:col: what (what pdrt does instead)"; with `strict` the first such line is an error.
#include "renderer/scene/pbrt/loop_subdivision.h"
#include "renderer/scene/pbrt/pbrt_parser.h"
#include "renderer/scene/scene_desc.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pdrt {

struct PbrtImport {
  SceneDesc scene;
  std::vector<std::string> report;  // unsupported features and unused parameters, in file order
};

// Bounds on the work a few lines of a scene file may ask for (a fuzzer lowers them to what one
// of its inputs may cost).
struct PbrtLimits {
  int64_t max_subdivided_triangles = kMaxSubdividedTriangles;  // per `loopsubdiv` shape
};

// Throws InputError for malformed or contradictory input (and, when strict, for the first
// report line).
PbrtImport build_pbrt_scene(const std::vector<PbrtDirective>& directives, bool strict, const PbrtLimits& limits = {});

// parse_pbrt_file + build_pbrt_scene; scene.file is set.
PbrtImport load_pbrt_scene(const std::filesystem::path& file, bool strict);

}  // namespace pdrt
