// Writes the benchmark scene (tessellated_scene.h) as OBJ + pdrt scene JSON, so that pdrt
// and Embree's tutorial `pathtracer` can render the very same geometry
// (bench/compare_embree_pathtracer.sh).
#include "tessellated_scene.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_bench_scene OUT_DIR\n");
    return 2;
  }
  std::string dir = argv[1];
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);  // a folder that cannot be made fails below
  pdrt::SceneDesc s = pdrt::bench::tessellated_scene(640, 480, 16, 4);
  std::ofstream obj(dir + "/bench.obj");
  obj << "# pdrt benchmark scene: tessellated sphere on a ground quad\nmtllib bench.mtl\nusemtl grey\n";
  uint32_t base = 1;
  for (const auto& shape : s.shapes) {
    for (const auto& p : shape.mesh.positions) {
      pdrt::Vec3 w = shape.transform.point(p);
      obj << "v " << w.x << " " << w.y << " " << w.z << "\n";
    }
    for (std::size_t i = 0; i < shape.mesh.indices.size(); i += 3)
      obj << "f " << base + shape.mesh.indices[i] << " " << base + shape.mesh.indices[i + 1] << " "
          << base + shape.mesh.indices[i + 2] << "\n";
    base += uint32_t(shape.mesh.positions.size());
  }
  std::ofstream mtl(dir + "/bench.mtl");
  mtl << "newmtl grey\nKd 0.6 0.6 0.6\nKs 0 0 0\n";
  std::ofstream json(dir + "/bench.json");
  json << R"({
  "camera": {"position": [0, 1.2, 3.2], "look_at": [0, 0.2, 0], "vfov_deg": 45},
  "film": {"width": 640, "height": 480, "filter": {"type": "box", "radius": 0.5}},
  "sampler": {"type": "poisson", "spp": 16, "seed": 1},
  "integrator": {"max_depth": 4, "rr_depth": 100},
  "objects": [{"type": "obj", "file": "bench.obj"}],
  "lights": [{"type": "environment", "radiance": [1, 1, 1]}]
}
)";
  obj.close(), mtl.close(), json.close();
  if (!obj || !mtl || !json) {
    std::fprintf(stderr, "make_bench_scene: cannot write the scene in %s\n", dir.c_str());
    return 1;
  }
  std::printf("wrote %s/bench.obj (%zu triangles), bench.mtl, bench.json\n", dir.c_str(),
              s.shapes[0].mesh.indices.size() / 3 + 2);
  return 0;
}
