// Issue 33: pdrt's thread scaling against raw Embree on the same scene (tessellated_scene.h,
// 510,722 triangles, 320x240, 4 spp), measured side by side in one run. Each round runs every
// workload at every thread count, interleaved (the order of the counts alternates between
// rounds: the machine is shared), and the table gives medians over rounds:
//   embree coherent     one rtcIntersect1 per camera ray (raw_embree_probe.h)
//   embree incoherent   one rtcIntersect1 per ray of hashed origin and direction
//   embree prim+shadow  bench_render's probe: camera ray, and an occlusion ray per hit
//   pdrt render         render() at max_depth 1 (camera, shadow and the MIS extension ray),
//                       the scene build excluded
// with Mrays/s, Mrays/s per thread, the speed-up over the first count, and Mrays per CPU-second
// with its ratio to the first count's (process CPU time: on a loaded machine the wall clock
// of N threads includes time other processes held the cores, the CPU clock does not, while
// threads that wait spinning do count: a ratio below 1 is work lost to waiting or contention).
// Then per count pdrt's speed-up over each probe's (wall, and per CPU-second), pdrt's rays/s
// over the prim+shadow probe's (bench_render's ratio), the share of pdrt's worker time spent
// inside tiles (the rest: waiting at the end of a wave or for work), and the heap allocations
// per sample of one extra, untimed render.
//   ./build/bench/thread_scaling [rounds (5)] [thread counts (1,2)]
#include "raw_embree_probe.h"
#include "renderer/render/process_cpu_time.h"
#include "renderer/render/renderer.h"
#include "tessellated_scene.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <vector>

using namespace pdrt;

namespace {

std::atomic<bool> g_counting{false};
std::atomic<int64_t> g_allocations{0};

}  // namespace

// Counts operator new while g_counting is set (one untimed render per thread count).
void* operator new(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
// The replaced new and delete are a matched pair over malloc/free; GCC 12 inlines delete into
// its callers and flags the free() of memory from `new` there (-Wmismatched-new-delete).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace {

constexpr int kW = 320, kH = 240, kSpp = 4;
const char* const kNames[] = {"embree coherent", "embree incoherent", "embree prim+shadow", "pdrt render"};
constexpr int kWorkloads = 4, kPdrt = 3;

struct Sample {
  double seconds = 0, cpu_seconds = 0;
  int64_t rays = 0;
  double busy = 0;  // pdrt: tile thread-seconds / (threads x seconds)
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Bench {
  SceneDesc scene = bench::tessellated_scene(kW, kH, kSpp, 1);
  EmbreeDevice device;
  EmbreeScene es{scene, device};
  ThinLensCamera cam{scene.camera, kW, kH};
  std::unique_ptr<Sampler> sampler = make_scene_sampler(scene.sampler, scene.film);

  Sample run(int workload, int threads) {
    Sample s;
    if (workload == kPdrt) {
      RenderOptions o;
      o.quiet = true, o.threads = threads;
      const RenderResult r = render(scene, *sampler, o);
      s.seconds = r.stats.seconds - r.stats.build_seconds, s.rays = r.stats.rays;
      s.cpu_seconds = r.stats.cpu_seconds - r.stats.build_cpu_seconds;
      const RankStats& k = r.stats.ranks.front();
      s.busy = k.tile_seconds / (r.stats.threads * (k.seconds - k.exchange_seconds));
      return s;
    }
    tbb::task_arena arena(threads);
    tbb::enumerable_thread_specific<int64_t> rays(0);
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = process_cpu_seconds();
    arena.execute([&] {
      if (workload == 1) {
        const uint64_t n = uint64_t(kW) * kH * kSpp * 2;
        tbb::parallel_for(tbb::blocked_range<uint64_t>(0, n, 4096), [&](const tbb::blocked_range<uint64_t>& r) {
          rays.local() += bench::trace_incoherent(es, r.begin(), r.end());
        });
      } else {
        tbb::parallel_for(tbb::blocked_range<int>(0, kH), [&](const tbb::blocked_range<int>& r) {
          rays.local() += bench::trace_camera_rows(es, cam, kW, kSpp, r.begin(), r.end(), workload == 2);
        });
      }
    });
    s.seconds = since(t0), s.cpu_seconds = process_cpu_seconds() - c0;
    for (int64_t n : rays) s.rays += n;
    return s;
  }

  double allocations_per_sample(int threads) {
    RenderOptions o;
    o.quiet = true, o.threads = threads;
    g_allocations = 0, g_counting = true;
    const RenderResult r = render(scene, *sampler, o);
    g_counting = false;
    return double(g_allocations.load()) / double(r.stats.samples);
  }
};

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  std::vector<int> counts;
  std::stringstream list(argc > 2 ? argv[2] : "1,2");
  for (std::string c; std::getline(list, c, ',');) counts.push_back(std::max(1, std::atoi(c.c_str())));
  Bench b;
  std::printf("scene: %zu triangles, %dx%d, %d spp; %d rounds, interleaved\n", b.es.triangle_count(), kW, kH, kSpp,
              rounds);
  std::map<std::pair<int, int>, std::vector<Sample>> got;  // (workload, threads)
  for (int r = 0; r < rounds; ++r)
    for (std::size_t i = 0; i < counts.size(); ++i) {
      const int t = counts[r % 2 ? counts.size() - 1 - i : i];
      for (int w = 0; w < kWorkloads; ++w) got[{w, t}].push_back(b.run(w, t));
    }
  auto mrays = [&](int w, int t, bool cpu = false) {
    std::vector<double> v;
    for (const Sample& s : got[{w, t}]) v.push_back(s.rays / (cpu ? s.cpu_seconds : s.seconds) * 1e-6);
    return median(v);
  };
  std::printf("\n%-20s %7s %10s %12s %9s %14s %10s\n", "workload", "threads", "Mrays/s", "per thread", "speed-up",
              "Mrays/CPU-s", "vs first");
  for (int w = 0; w < kWorkloads; ++w)
    for (int t : counts)
      std::printf("%-20s %7d %10.2f %12.2f %9.3f %14.2f %10.3f\n", kNames[w], t, mrays(w, t), mrays(w, t) / t,
                  mrays(w, t) / mrays(w, counts.front()), mrays(w, t, true),
                  mrays(w, t, true) / mrays(w, counts.front(), true));
  // pdrt's speed-up over each probe's (wall clock, then rays per CPU-second), its rays/s over
  // the prim+shadow probe's (wall, CPU), the workers' busy share and the allocations.
  std::printf("\n%7s %-26s %-26s %-16s %-6s %s\n", "threads", "speed-up / raw's (wall)", "per CPU-s / raw's",
              "pdrt / p+s rays", "busy", "allocs/sample");
  std::printf("%7s %-26s %-26s %-16s\n", "", "coh / incoh / p+s", "coh / incoh / p+s", "wall / CPU");
  for (int t : counts) {
    auto up = [&](int w, bool cpu) { return mrays(w, t, cpu) / mrays(w, counts.front(), cpu); };
    std::vector<double> busy;
    for (const Sample& s : got[{kPdrt, t}]) busy.push_back(s.busy);
    char wall[64], cpu[64], rays[64];
    std::snprintf(wall, sizeof wall, "%.3f / %.3f / %.3f", up(kPdrt, false) / up(0, false),
                  up(kPdrt, false) / up(1, false), up(kPdrt, false) / up(2, false));
    std::snprintf(cpu, sizeof cpu, "%.3f / %.3f / %.3f", up(kPdrt, true) / up(0, true), up(kPdrt, true) / up(1, true),
                  up(kPdrt, true) / up(2, true));
    std::snprintf(rays, sizeof rays, "%.3f / %.3f", mrays(kPdrt, t) / mrays(2, t),
                  mrays(kPdrt, t, true) / mrays(2, t, true));
    std::printf("%7d %-26s %-26s %-16s %-6.3f %.4f\n", t, wall, cpu, rays, median(busy), b.allocations_per_sample(t));
  }
  return 0;
}
