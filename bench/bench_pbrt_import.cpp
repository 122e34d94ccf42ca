// pbrt-v4 import speed (issue 18): a binary PLY mesh of about a million triangles (a 708 x 708
// vertex grid, 999,698 triangles, 19 MB) referenced by a .pbrt file, loaded end to end (parse,
// PLY check, Assimp read, orientation pass). Target: <= 2 s per load.
// Run: ./build/bench/bench_pbrt_import
#include "renderer/scene/pbrt/pbrt_scene_builder.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path write_grid(int n) {
  const fs::path dir = fs::temp_directory_path() / ("pdrt_bench_ply_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const int64_t faces = 2 * int64_t(n - 1) * (n - 1);
  std::ofstream out(dir / "grid.ply", std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << int64_t(n) * n
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << faces
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float v[3] = {float(i) / (n - 1), 0, float(j) / (n - 1)};
      out.write(reinterpret_cast<const char*>(v), sizeof v);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int32_t a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      const unsigned char three = 3;
      const int32_t t0[3] = {a, c, b}, t1[3] = {a, d, c};
      out.write(reinterpret_cast<const char*>(&three), 1);
      out.write(reinterpret_cast<const char*>(t0), sizeof t0);
      out.write(reinterpret_cast<const char*>(&three), 1);
      out.write(reinterpret_cast<const char*>(t1), sizeof t1);
    }
  std::ofstream(dir / "grid.pbrt") << "LookAt 0 3 0  0 0 0  0 0 1\nCamera \"perspective\"\nWorldBegin\n"
                                      "LightSource \"infinite\"\nShape \"plymesh\" \"string filename\" \"grid.ply\"\n";
  return dir;
}

void BM_LoadMillionTrianglePly(benchmark::State& state) {
  const fs::path dir = write_grid(708);
  for (auto _ : state) {
    pdrt::PbrtImport im = pdrt::load_pbrt_scene(dir / "grid.pbrt", false);
    benchmark::DoNotOptimize(im.scene.shapes.data());
    state.counters["triangles"] = double(im.scene.shapes[0].mesh.indices.size() / 3);
  }
  fs::remove_all(dir);
}
BENCHMARK(BM_LoadMillionTrianglePly)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
