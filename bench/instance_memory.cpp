// Memory and time of object instancing (SceneDesc::prototypes / instances, Embree instances):
// a 20 000-triangle mesh placed 1, 10 000 (instances) and 100 times (copied shapes), each
// scene loaded into Embree and rendered at 64x64, 1 spp, in its own forked process so that
// each peak RSS (getrusage ru_maxrss) is its own. Not a timed test; prints a table.
//   ./build/bench/instance_memory [instances (10000)] [copies (100)]
#include "renderer/render/renderer.h"
#include "tessellated_scene.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace pdrt;

namespace {

SceneDesc grid_scene(int count, bool instanced) {
  SceneDesc s;
  const int side = int(std::ceil(std::sqrt(double(count))));
  s.camera.position = {0, float(side) * 0.6f, float(side) * 0.8f}, s.camera.look_at = {0, 0, 0}, s.camera.vfov_deg = 60;
  s.film.width = s.film.height = 64;
  s.film.filter.type = FilterType::Box, s.film.filter.radius = 0.5f;
  s.sampler.type = "random", s.sampler.spp = 1, s.sampler.seed = 1;
  s.integrator.max_depth = 2;
  s.environment.radiance = Vec3(1.0f);
  Material m;
  m.name = "grey", m.type = MaterialType::Diffuse, m.albedo = Vec3(0.6f);
  s.materials.push_back(m);
  ShapeDesc mesh;
  mesh.mesh = bench::uv_sphere(100, 101, 0.45f);  // 2 * 100 * 100 = 20 000 triangles
  if (instanced) s.prototypes.push_back({"ball", {mesh}, ""});
  for (int i = 0; i < count; ++i) {
    const Affine at = Affine::translate({float(i % side - side / 2), 0, float(i / side - side / 2)});
    if (instanced) {
      InstanceDesc in;
      in.transform = at;
      s.instances.push_back(in);
    } else {
      ShapeDesc c = mesh;
      c.transform = at;
      s.shapes.push_back(std::move(c));
    }
  }
  return s;
}

struct Measure {
  double seconds = 0;
  long peak_kb = 0;
  double covered = 0;  // fraction of pixels darker than the white environment: the meshes are seen
};

// In a child process: build the scene, render it, report the time and the child's peak RSS.
Measure measure(int count, bool instanced) {
  int fd[2];
  if (pipe(fd) != 0) std::exit(1);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    const auto t0 = std::chrono::steady_clock::now();
    SceneDesc s = grid_scene(count, instanced);
    auto sampler = make_scene_sampler(s.sampler, s.film);
    RenderOptions o;
    o.quiet = true;
    RenderResult r = render(s, *sampler, o);
    Measure m;
    for (std::size_t i = 0; i < r.image.rgb.size(); i += 3)
      m.covered += r.image.rgb[i] < 0.99f ? 3.0 / r.image.rgb.size() : 0.0;
    m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    m.peak_kb = ru.ru_maxrss;
    if (write(fd[1], &m, sizeof m) != ssize_t(sizeof m)) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  Measure m;
  if (read(fd[0], &m, sizeof m) != ssize_t(sizeof m)) std::fprintf(stderr, "child failed\n");
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const int instances = argc > 1 ? std::atoi(argv[1]) : 10000, copies = argc > 2 ? std::atoi(argv[2]) : 100;
  const Measure one = measure(1, true), many = measure(instances, true), copied = measure(copies, false);
  const Measure base = measure(1, false);
  std::printf("%-34s %12s %10s %8s\n", "scene (20 000-triangle mesh)", "peak RSS MB", "seconds", "covered");
  auto row = [](const std::string& name, const Measure& m) {
    std::printf("%-34s %12.1f %10.2f %8.2f\n", name.c_str(), m.peak_kb / 1024.0, m.seconds, m.covered);
  };
  row("1 shape (no instancing)", base);
  row("1 instance", one);
  row(std::to_string(instances) + " instances", many);
  row(std::to_string(copies) + " copied shapes", copied);
  std::printf(
      "per instance: %.0f bytes; per copy: %.0f bytes (%.0fx)\n",
      double(many.peak_kb - one.peak_kb) * 1024 / (instances - 1),
      double(copied.peak_kb - base.peak_kb) * 1024 / (copies - 1),
      (double(copied.peak_kb - base.peak_kb) / (copies - 1)) / (double(many.peak_kb - one.peak_kb) / (instances - 1)));
  return 0;
}
