#pragma once
// Small scenes built in code for the analytic renderer tests.
#include "renderer/render/renderer.h"
#include "renderer/render/thin_lens_camera.h"
#include "renderer/scene/scene_desc.h"

#include <string>
#include <utility>
#include <vector>

#include <cmath>

namespace pdrt::test {

// Placement of a whole scene: p -> offset + scale p (tests that a scene renders the same
// wherever it is and at whatever scale).
struct Placement {
  Vec3 offset;
  float scale;
  Vec3 point(const Vec3& p) const { return offset + p * scale; }
  Vec3 vector(const Vec3& v) const { return v * scale; }
};

inline std::string describe(const Placement& at) {
  return "offset (" + std::to_string(at.offset.x) + ", " + std::to_string(at.offset.y) + ", " +
         std::to_string(at.offset.z) + ") scale " + std::to_string(at.scale);
}

inline int add_material(SceneDesc& s, Material m) {
  s.materials.push_back(std::move(m));
  return int(s.materials.size()) - 1;
}

inline Material diffuse(float albedo) {
  Material m;
  m.name = "diffuse";
  m.type = MaterialType::Diffuse;
  m.albedo = Vec3(albedo);
  return m;
}

inline Material emitter(float radiance, bool two_sided = false) {
  Material m;
  m.name = "emitter";
  m.type = MaterialType::Emitter;
  m.radiance = Vec3(radiance);
  m.two_sided = two_sided;
  return m;
}

// A smooth (roughness 0) or rough glass of index `ior`, lossless.
inline Material glass(float ior, float roughness = 0) {
  Material m;
  m.name = "glass";
  m.type = MaterialType::Dielectric;
  m.ior = ior;
  m.roughness = roughness;
  m.albedo = Vec3(1.0f);
  return m;
}

// A quad corner, corner+e1, corner+e1+e2, corner+e2; its front face is cross(e1, e2); uv as the loader's.
inline ShapeDesc quad(Vec3 corner, Vec3 e1, Vec3 e2, int material) {
  ShapeDesc s;
  s.kind = ShapeDesc::Kind::Mesh;
  s.mesh.positions = {corner, corner + e1, corner + e1 + e2, corner + e2};
  s.mesh.indices = {0, 1, 2, 0, 2, 3};
  s.mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // as the loader's quads
  s.material = material;
  return s;
}

inline ShapeDesc sphere(Vec3 center, float radius, int material) {
  ShapeDesc s;
  s.kind = ShapeDesc::Kind::Sphere;
  s.center = center;
  s.radius = radius;
  s.material = material;
  return s;
}

// Form factor from a point to the rectangle [0,x]x[0,y] at height h whose corner is
// straight above the point (parallel planes), extended to signed extents.
inline double corner_form_factor(double x, double y, double h) {
  double X = std::abs(x) / h, Y = std::abs(y) / h;
  double a = std::sqrt(1 + X * X), b = std::sqrt(1 + Y * Y);
  double f = (X / a * std::atan(Y / a) + Y / b * std::atan(X / b)) / (2 * M_PI);
  return (x < 0 ? -f : f) * (y < 0 ? -1 : 1);
}

// Form factor from the point (px, 0, pz) with normal +y to the rectangle [x0,x1]x[z0,z1] at
// height h facing down.
inline double rect_form_factor(double px, double pz, double x0, double x1, double z0, double z1, double h) {
  return corner_form_factor(x1 - px, z1 - pz, h) - corner_form_factor(x0 - px, z1 - pz, h) -
         corner_form_factor(x1 - px, z0 - pz, h) + corner_form_factor(x0 - px, z0 - pz, h);
}

inline SceneDesc base_scene(int width, int height, int spp) {
  SceneDesc s;
  s.film.width = width, s.film.height = height;
  s.film.filter.type = FilterType::Box;
  s.film.filter.radius = 0.5f;
  s.sampler.spp = spp;
  s.sampler.type = "poisson";
  s.sampler.seed = 7;
  return s;
}

// A white furnace: a unit sphere of material `m` at `centre`, seen head-on from 4 units
// (vertical field of view 30 degrees) in a white environment.
inline SceneDesc furnace_sphere(int width, int height, int spp, Vec3 centre, Material m) {
  SceneDesc s = base_scene(width, height, spp);
  s.camera.position = centre + Vec3(0, 0, 4), s.camera.look_at = centre, s.camera.vfov_deg = 30;
  s.environment.radiance = Vec3(1.0f);
  s.shapes.push_back(sphere(centre, 1, add_material(s, std::move(m))));
  return s;
}

// The pixels of furnace_sphere()'s image whose centres lie within `fraction` of a radius the
// silhouette contains.
// A lit diffuse sphere on a 40 x 24 film in front of a dim environment, Gaussian filter of
// radius 1.5: pixels that differ from sample to sample.
inline SceneDesc lit_sphere(int spp, const char* sampler) {
  SceneDesc s = base_scene(40, 24, spp);
  s.sampler.type = sampler;
  s.film.filter.type = FilterType::Gaussian, s.film.filter.radius = 1.5f;
  s.camera.position = Vec3(0, 0, 4), s.camera.look_at = Vec3(0, 0, 0), s.camera.vfov_deg = 40;
  s.environment.radiance = Vec3(0.2f);
  s.shapes.push_back(sphere(Vec3(0, 0, 0), 1, add_material(s, diffuse(0.7f))));
  s.shapes.push_back(sphere(Vec3(2, 2, 2), 0.5f, add_material(s, emitter(8))));
  return s;
}

inline std::vector<std::pair<int, int>> pixels_inside_silhouette(const SceneDesc& s, Vec3 centre, double fraction) {
  const int W = s.film.width, H = s.film.height;
  ThinLensCamera cam(s.camera, W, H);
  const double rad = fraction * (cam.project(centre + Vec3(0.5f, 0, 1))[0] - W / 2.0);
  std::vector<std::pair<int, int>> px;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const double dx = x + 0.5 - W / 2.0, dy = y + 0.5 - H / 2.0;
      if (dx * dx + dy * dy <= rad * rad) px.emplace_back(x, y);
    }
  return px;
}

// Mean of the three channels of pixel (x, y).
inline double mean_rgb(const Image& im, int x, int y) {
  std::size_t i = 3 * (std::size_t(y) * im.width + x);
  return (im.rgb[i] + im.rgb[i + 1] + im.rgb[i + 2]) / 3.0;
}

inline RenderResult render_quietly(const SceneDesc& s, int threads = 0) {
  auto sampler = make_scene_sampler(s.sampler, s.film);
  RenderOptions o;
  o.quiet = true;
  o.threads = threads;
  return render(s, *sampler, o);
}

}  // namespace pdrt::test
