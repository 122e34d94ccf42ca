#pragma once
// The parsed, validated scene: what scene_loader produces from a scene JSON file
// (docs/scene-format.md) and the renderer consumes. Everything here is already checked:
// finite numbers, positive sizes, material indices in range, non-degenerate triangles.
#include "renderer/scene/material.h"
#include "renderer/scene/settings_names.h"
#include "renderer/scene/texture_desc.h"
#include "renderer/scene/transform.h"
#include "sampling/samplers/sampler_names.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

struct CameraKey {
  float time = 0;
  Vec3 position, look_at;
};

struct CameraDesc {
  Vec3 position{0, 0, 5}, look_at{0, 0, 0}, up{0, 1, 0};
  float vfov_deg = 40;
  float aperture_radius = 0;  // 0 = pinhole
  float focus_distance = 0;   // <= 0 in the file means |look_at - position|; resolved by the loader
  int aperture_blades = 0;    // 0 = circular aperture, >= 3 = regular polygon
  float aperture_rotation_deg = 0;
  float shutter_open = 0, shutter_close = 1;
  // The film's x axis runs along up x forward instead of forward x up: the image mirrored left
  // to right, as pbrt's left-handed camera space gives it (pbrt import, docs/pbrt-import.md).
  bool flip_x = false;
  std::vector<CameraKey> motion;  // optional; sorted by time; overrides position/look_at when present
  // pbrt-v4 §5.2: parallel rays along the view direction instead of rays from the eye.
  enum class Projection { Perspective, Orthographic } projection = Projection::Perspective;
  float ortho_height = 2;  // orthographic: the film's vertical extent in scene units (default window)
  // pbrt-v4's screen window [x0, x1, y0, y1]: the film's extent on the plane at distance 1
  // (perspective) or in scene units (orthographic), along right and up; x0 < x1, y0 < y1.
  // Off-centre windows give shifted (sheared) frusta. Unset: centred, from vfov_deg or
  // ortho_height and the film's aspect (renderer/render/screen_window.h).
  bool has_screen_window = false;
  std::array<float, 4> screen_window{-1, 1, -1, 1};
};

enum class FilterType { Box, Tent, Gaussian, Mitchell };

struct FilterDesc {
  FilterType type = FilterType::Gaussian;
  float radius = 1.5f;  // pixels (Cook's w = 1.5 for the Gaussian)
  // Gaussian only: 0 is Cook's radial e^(-d^2) - e^(-w^2); > 0 is pbrt-v4's separable
  // Gaussian of this standard deviation in pixels, (g(x) - g(w)) (g(y) - g(w)).
  float sigma = 0;
  Reconstruction reconstruction = Reconstruction::Importance;
};

struct FilmDesc {
  int width = 512, height = 512;
  FilterDesc filter;
  float exposure = 0;               // stops: pixel values are scaled by 2^exposure
  std::string size_where = "film";  // "scene.json:3:21: film.width" for messages about the size
  // pbrt-v4's crop window [x0, x1, y0, y1] in [0, 1] of the film (y down): pixels
  // ceil(width x0) .. ceil(width x1) - 1 etc. are rendered, with the full film's camera and
  // sample coordinates, and the image has the cropped size (renderer/render/crop_window.h).
  std::array<float, 4> crop_window{0, 1, 0, 1};
};

struct AdaptiveDesc {
  bool enabled = false;
  int min_spp = 4, max_spp = 256;
  float threshold = 0;  // 0 = the metric's own default (adaptive_metric.h)
  AdaptiveMetricKind metric = AdaptiveMetricKind::ErrorPerSample;
  AdaptiveVariance variance = AdaptiveVariance::Samples;
  AdaptiveDecision decision = AdaptiveDecision::Shared;
};

struct SamplerDesc {
  std::string type = sampler_name(SamplerKind::Poisson);  // one of kSamplerNames
  std::string type_where = "sampler.type";                // "scene.json:5:13: sampler.type" for messages
  int spp = 16;
  uint64_t seed = 0;
  AdaptiveDesc adaptive;
};

struct IntegratorDesc {
  int max_depth = 8;  // path vertices after the camera
  int rr_depth = 3;   // Russian roulette from this depth on
  // Path regularisation (biased, off by default): after the first non-delta scattering, vertices
  // shade with regularized(material) (render/bsdf.h), which roughens near-specular lobes.
  bool regularize = false;
  // How next-event estimation samples the environment (settings_names.h). Compensated is
  // pbrt-v4's path integrator (allowIncompletePDF in UniformInfiniteLight and
  // ImageInfiniteLight): every pbrt import sets it.
  EnvironmentSampling environment_sampling = EnvironmentSampling::Full;
};

struct MeshData {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;      // per vertex, optional (empty = flat shading)
  std::vector<uint32_t> indices;  // triangles, 3 per face
  // Per vertex, optional (empty: each triangle's barycentric (b1, b2), so vertex 0 is (0, 0),
  // 1 is (1, 0), 2 is (0, 1)). Quads get (0,0) (1,0) (1,1) (0,1) from corner, edge1, edge2.
  std::vector<std::array<float, 2>> uvs;
};

struct ShapeDesc {
  enum class Kind { Mesh, Sphere } kind = Kind::Mesh;
  MeshData mesh;      // Kind::Mesh, in object space
  Vec3 center{0.0f};  // Kind::Sphere, object space
  float radius = 1;
  int material = 0;               // index into SceneDesc::materials
  Affine transform;               // object to world (static part)
  std::vector<MotionKey> motion;  // optional: world(t) = interpolate(motion, t) * transform
  std::string where;              // "scene.json: objects[2]" for messages
};

// A named group of shapes placed any number of times by instances (docs/scene-format.md,
// "prototypes"). Its shapes are in the prototype's own space (each with its static transform,
// no motion: Embree instances one level deep) and carry no emitter material: pbrt-v4 refuses
// area lights in instances, and the loader does too. A renderer given emitters here anyway
// sees them only through BSDF sampling (they are not in the light set).
struct PrototypeDesc {
  std::string name;
  std::vector<ShapeDesc> shapes;
  std::string where;  // "scene.json: prototypes.tree" for messages
};

// One placement of a prototype: world(t) = interpolate(motion, t) * transform * prototype
// shape's transform, traced as an Embree instance of the prototype's one BVH.
struct InstanceDesc {
  int prototype = 0;              // index into SceneDesc::prototypes
  Affine transform;               // prototype to world (static part)
  std::vector<MotionKey> motion;  // optional, as ShapeDesc::motion
  std::string where;              // "scene.json: objects[4]" for messages
};

// The environment light (docs/scene-format.md, "environment"): a constant radiance, or an
// equirectangular image (renderer/scene/equirect.h: row 0 is +y, the image centre -z)
// times `scale`, turned by rotation_deg about +y.
struct EnvironmentDesc {
  Vec3 radiance{0.0f};        // constant radiance from every direction (no image)
  std::string file;           // the image as found (for messages); empty = constant
  int width = 0, height = 0;  // texels of the image; 0 = constant
  std::vector<float> rgb;     // width * height linear RGB, top row first; finite, >= 0
  Vec3 scale{1.0f};           // multiplies the image, per channel, >= 0
  float rotation_deg = 0;     // about +y, counter-clockwise seen from above
  bool resampled = false;     // rgb is not `file` itself (a pbrt-v4 octahedral map made equirectangular)
  bool has_map() const { return width > 0 && height > 0; }
};

// A light without area (docs/scene-format.md, "lights"): next-event estimation reaches it,
// no ray ever hits it, so it takes no part in MIS (its light sample has weight 1).
//   Point    radiant intensity `intensity` from `position` into every direction
//   Spot     the same on its axis `direction`, smoothstep falloff from cos_falloff_start down
//            to cos_cone, none past the cone (pbrt-v4's SpotLight)
//   Distant  parallel light travelling along `direction`; `irradiance` on a surface facing it
//            (pbrt-v4's DistantLight `L`)
struct DeltaLightDesc {
  enum class Kind { Point, Spot, Distant } kind = Kind::Point;
  Vec3 position{0.0f};            // point, spot: object space
  Vec3 direction{0, 0, -1};       // unit; spot: the cone's axis (object space); distant: the way light travels (world)
  Vec3 intensity{0.0f};           // point, spot: W/sr per channel (spot: on its axis)
  Vec3 irradiance{0.0f};          // distant: W/m^2 per channel on a surface facing the light
  float cos_cone = -1;            // spot: cosine of the cone's half-angle (nothing past it)
  float cos_falloff_start = -1;   // spot: cosine of the half-angle where the falloff begins (>= cos_cone)
  Affine transform;               // point, spot: object to world (static part)
  std::vector<MotionKey> motion;  // point, spot: world(t) = interpolate(motion, t) * transform
};

struct SceneDesc {
  std::filesystem::path file;  // the scene file; relative paths resolve against its directory
  CameraDesc camera;
  FilmDesc film;
  SamplerDesc sampler;
  IntegratorDesc integrator;
  std::vector<Material> materials;
  std::vector<TextureDesc> textures;  // referred to by Material::textures and by each other
  std::vector<ShapeDesc> shapes;      // objects and area lights (lights carry emitter materials)
  EnvironmentDesc environment;
  std::vector<DeltaLightDesc> delta_lights;  // point, spot and distant lights
  int64_t degenerate_triangles = 0;          // skipped while loading (the loader warns once)
  std::vector<PrototypeDesc> prototypes;     // shape groups placed by `instances`
  std::vector<InstanceDesc> instances;
};

// Whether anything moves during the shutter (camera, shapes, instances, point and spot
// lights): otherwise the shutter time changes no ray, hit or light sample.
inline bool has_motion(const SceneDesc& s) {
  auto moves = [](const auto& v) {
    for (const auto& x : v)
      if (!x.motion.empty()) return true;
    return false;
  };
  return !s.camera.motion.empty() || moves(s.shapes) || moves(s.instances) || moves(s.delta_lights);
}

}  // namespace pdrt
