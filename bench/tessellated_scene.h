#pragma once
// The benchmark scene: a finely tessellated sphere (>= 500k triangles) on a ground quad
// under a constant white environment, shared by bench_render and make_bench_scene.
#include "renderer/scene/scene_desc.h"

#include <cmath>

namespace pdrt::bench {

inline MeshData uv_sphere(int n_phi, int n_theta, float radius) {
  MeshData m;
  for (int j = 0; j <= n_theta; ++j)
    for (int i = 0; i <= n_phi; ++i) {
      float th = kPi * j / n_theta, ph = 2 * kPi * i / n_phi;
      Vec3 n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
      m.positions.push_back(n * radius);
      m.normals.push_back(n);
    }
  auto v = [&](int i, int j) { return uint32_t(j * (n_phi + 1) + i); };
  for (int j = 0; j < n_theta; ++j)
    for (int i = 0; i < n_phi; ++i) {
      // Counter-clockwise seen from outside; pole rows keep their (thin) triangles.
      if (j > 0) m.indices.insert(m.indices.end(), {v(i, j), v(i + 1, j), v(i, j + 1)});
      if (j < n_theta - 1) m.indices.insert(m.indices.end(), {v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  return m;
}

inline SceneDesc tessellated_scene(int width, int height, int spp, int max_depth) {
  SceneDesc s;
  s.camera.position = {0, 1.2f, 3.2f}, s.camera.look_at = {0, 0.2f, 0}, s.camera.vfov_deg = 45;
  s.film.width = width, s.film.height = height;
  s.film.filter.type = FilterType::Box, s.film.filter.radius = 0.5f;
  s.sampler.type = "poisson", s.sampler.spp = spp, s.sampler.seed = 1;
  s.integrator.max_depth = max_depth;
  Material m;
  m.name = "grey", m.type = MaterialType::Diffuse, m.albedo = Vec3(0.6f);
  s.materials.push_back(m);
  ShapeDesc sphere;
  sphere.mesh = uv_sphere(640, 400, 1.0f);  // 2 * 640 * 399 = 510720 triangles
  sphere.transform = Affine::translate({0, 1, 0});
  s.shapes.push_back(sphere);
  ShapeDesc ground;
  ground.mesh.positions = {{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}};
  ground.mesh.indices = {0, 1, 2, 0, 2, 3};
  s.shapes.push_back(ground);
  s.environment.radiance = Vec3(1.0f);
  return s;
}

}  // namespace pdrt::bench
