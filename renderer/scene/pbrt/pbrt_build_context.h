#pragma once
// What the pbrt importer's translators share while pbrt_scene_builder.cpp walks the directives:
// the scene being built and its report, the graphics state (pbrt_graphics_state.h), the camera
// parameters resolved once the film is known, the texture table, and the parameter readers
// every kind uses. Internal to renderer/scene/pbrt/.
//
// The translators, one entry point per kind of directive:
//   pbrt_camera.cpp     Camera, Film, PixelFilter, Sampler, Integrator (translate_pbrt_option)
//   pbrt_textures.cpp   Texture (translate_pbrt_texture)
//   pbrt_materials.cpp  Material, MakeNamedMaterial, NamedMaterial (translate_pbrt_material)
//   pbrt_lights.cpp     LightSource, AreaLightSource (translate_pbrt_light)
//   pbrt_shapes.cpp     Shape (translate_pbrt_shape)
#include "renderer/scene/pbrt/pbrt_graphics_state.h"
#include "renderer/scene/pbrt/pbrt_scene_builder.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pdrt {

constexpr double kPbrtPi = 3.14159265358979323846;

// The camera's parameters that need the film's resolution (pbrt_camera.cpp).
struct PbrtCameraState {
  bool seen = false;
  PbrtLocation at;
  float fov = 90;
  std::optional<std::array<float, 4>> screen_window;  // pbrt's, in screen space
  std::optional<float> frame_aspect;
  std::array<float, 2> scale{1, 1};  // camera space's x and y unit in scene units
};

struct PbrtBuild {
  explicit PbrtBuild(bool strict_) : strict(strict_) {}

  bool strict;
  PbrtLimits limits;
  PbrtImport out;
  PbrtGraphicsState gs;
  PbrtCameraState camera;
  std::optional<PbrtLocation> last;  // the latest directive
  struct NoteKind {
    std::size_t line;  // index into out.report
    int more = 0;
    PbrtLocation last;
  };
  std::map<std::string, NoteKind> note_kinds;
  int default_material = -1;
  std::vector<long long> texture_cost;             // per scene texture: texture_node_cost
  std::map<std::string, int> textures;             // "float:name" / "spectrum:name" -> index, -1 unsupported
  std::vector<TextureBinding>* bind_to = nullptr;  // where color() binds a texture parameter
  MaterialParam bind_param = MaterialParam::Albedo;

  // ---- reporting: "file:line:col: what", an error under --strict. One line per kind (the
  // message itself unless `kind` names a family of messages); later ones of a kind are counted
  // on its first line by finish_report.
  void note(const PbrtLocation& at, const std::string& what, const std::string& kind = "");
  void finish_report();
  // A colour pdrt multiplies per RGB channel where pbrt-v4 works per wavelength (reported).
  void note_rgb(const PbrtLocation& at, const std::string& what);
  void report_unused(const std::vector<PbrtParam>& params);
  [[noreturn]] static void fail(const PbrtLocation& at, const std::string& what);

  // Places a shape or light whose object space the CTM maps to world: a static transform, or
  // two keyframes at the TransformTimes.
  void place(const PbrtLocation& at, Affine* transform, std::vector<MotionKey>* motion);

  // ---- parameters
  // rgb, blackbody, spectrum or a single float; a texture binds to bind_to when set.
  Vec3 color(const PbrtParams& ps, const std::string& name, Vec3 fallback, bool emission);
  float positive(const PbrtParams& ps, const std::string& name, float fallback, bool allow_zero = false);

  // ---- textures
  // A texture parameter's texture, or nullopt when it names none we have (reported).
  std::optional<int> texture_ref(const PbrtParam& p, const std::string& kind);
  // A texture input: a number, an rgb or a texture.
  TextureInput texture_input(const PbrtParams& ps, const std::string& name, float fallback, const std::string& kind);
  // A texture the importer adds (a roughness remap, an imagemap's scale or invert): appended
  // after its inputs, so the evaluation cost is known from theirs (kMaxTextureEvaluation).
  int add_texture(TextureDesc t, const std::string& name, const PbrtLocation& at);

  // The current material's index, creating pbrt's default (diffuse 0.5) on first use.
  int current_material();
};

// Camera, Film, PixelFilter, Sampler, Integrator (pbrt_camera.cpp).
void translate_pbrt_option(PbrtBuild& b, const PbrtDirective& d);
// pbrt-v4's values for the options a file leaves out: Film 1280 x 720, the Gaussian filter of
// radius 1.5 and sigma 0.5, maximum depth 5, the zsobol sampler at 16 spp (docs/pbrt-import.md).
void apply_pbrt_defaults(SceneDesc& s);
// pbrt-v4's default camera when the file has none; then the screen window and pdrt's vertical
// field of view from the film's resolution.
void finish_pbrt_camera(PbrtBuild& b);
// Texture (pbrt_textures.cpp).
void translate_pbrt_texture(PbrtBuild& b, const PbrtDirective& d);
// Material, MakeNamedMaterial, NamedMaterial (pbrt_materials.cpp).
void translate_pbrt_material(PbrtBuild& b, const PbrtDirective& d);
// LightSource, AreaLightSource (pbrt_lights.cpp).
void translate_pbrt_light(PbrtBuild& b, const PbrtDirective& d);
// Shape (pbrt_shapes.cpp).
void translate_pbrt_shape(PbrtBuild& b, const PbrtDirective& d);

}  // namespace pdrt
