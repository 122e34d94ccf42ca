#pragma once
// Reads a JSON scene file (docs/scene-format.md) and the OBJ/MTL files it names into a
// validated SceneDesc; a file named *.pbrt is read as a pbrt-v4 scene instead
// (docs/pbrt-import.md), and what pdrt cannot represent of it is listed on stderr, one line
// each, or with `strict` refused at the first such line. Every problem is an InputError whose one-line message starts
// with file:line:col and the JSON path, e.g. "scene.json:12:7: objects[2].radius must be > 0, got -1".
#include "renderer/scene/scene_desc.h"

#include <filesystem>

namespace pdrt {

// Relative paths in the file resolve against the file's directory. Prints one warning line
// to stderr when degenerate triangles were skipped.
SceneDesc load_scene(const std::filesystem::path& file, bool strict = false);

// Whether `file` is read as a pbrt-v4 scene (its extension is .pbrt).
bool is_pbrt_scene(const std::filesystem::path& file);

}  // namespace pdrt
