// `pdrt convert`: a scene (pbrt-v4 or pdrt JSON) written as pdrt's JSON format, meshes as OBJ
// files beside it (renderer/scene/scene_writer.h), so an imported scene can be edited in pdrt's
// own format. What pdrt cannot represent is reported as `render` reports it.
#include "app/commands.h"
#include "app/output_path.h"
#include "renderer/scene/scene_loader.h"
#include "renderer/scene/scene_writer.h"
#include "sampling/core/errors.h"

#include <cstdio>
#include <memory>

namespace pdrt::cli {

void add_convert_command(CLI::App& app) {
  struct Opts {
    std::string scene, out;
    bool strict = false, quiet = false, inline_meshes = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("convert",
                                 "Write a scene (pbrt-v4 *.pbrt or pdrt JSON) as pdrt JSON, meshes as OBJ beside it.");
  cmd->add_option("scene", o->scene, "Scene file: pdrt JSON, or pbrt-v4 (*.pbrt)")->required();
  cmd->add_option("--out,-o", o->out, "The JSON file to write (meshes go to NAME.meshes/ beside it)")->required();
  cmd->add_flag("--strict", o->strict, "pbrt scenes: refuse anything pdrt cannot represent instead of listing it");
  cmd->add_flag("--inline-meshes", o->inline_meshes, "Write triangle meshes into the JSON itself instead of OBJ files");
  cmd->add_flag("--quiet,-q", o->quiet, "No summary on stderr");
  cmd->callback([o] {
    require_output_path("--out", o->out);
    if (std::filesystem::path(o->out).extension() != ".json")
      throw UsageError("--out: the converted scene is JSON; give a name ending in .json, got \"" + o->out + "\"");
    SceneDesc scene = load_scene(o->scene, o->strict);
    write_scene_json(scene, o->out, {o->inline_meshes});
    if (!o->quiet)
      std::fprintf(stderr, "pdrt convert: %s: %zu shapes, %zu materials, %zu textures\n", o->out.c_str(),
                   scene.shapes.size(), scene.materials.size(), scene.textures.size());
  });
}

}  // namespace pdrt::cli
