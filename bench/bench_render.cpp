// Issue 4 speed target: on a >= 500k-triangle scene, pdrt's rays per second (primary +
// shadow, max_depth 1) against raw rtcIntersect1 + rtcOccluded1 throughput on the same
// scene, camera, resolution and threads. Both report rays/s as items_per_second.
#include "raw_embree_probe.h"
#include "renderer/render/embree_scene.h"
#include "renderer/render/renderer.h"
#include "tessellated_scene.h"
#include "renderer/render/thin_lens_camera.h"

#include <benchmark/benchmark.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <chrono>

using namespace pdrt;

namespace {

constexpr int kW = 320, kH = 240, kSpp = 4;

const SceneDesc& scene() {
  static SceneDesc s = bench::tessellated_scene(kW, kH, kSpp, 1);
  return s;
}

// Raw Embree: one primary ray per sample through a hashed pixel position, and on a hit one
// occlusion ray toward a hashed direction of the upper hemisphere (raw_embree_probe.h).
void BM_RawEmbreePrimaryShadow(benchmark::State& state) {
  EmbreeDevice device;
  EmbreeScene es(scene(), device);
  ThinLensCamera cam(scene().camera, kW, kH);
  int64_t total = 0;
  for (auto _ : state) {
    tbb::enumerable_thread_specific<int64_t> rays(0);
    tbb::parallel_for(tbb::blocked_range<int>(0, kH), [&](const tbb::blocked_range<int>& r) {
      rays.local() += bench::trace_camera_rows(es, cam, kW, kSpp, r.begin(), r.end(), true);
    });
    for (int64_t n : rays) total += n;
  }
  state.SetItemsProcessed(total);
  state.counters["triangles"] = double(es.triangle_count());
}

// pdrt itself, max_depth 1 (primary, shadow and the MIS extension ray), manual time = the
// rendering only (the BVH build is excluded, as for the raw loop).
void BM_PdrtRenderDirect(benchmark::State& state) {
  auto sampler = make_scene_sampler(scene().sampler, scene().film);
  RenderOptions o;
  o.quiet = true;
  int64_t total = 0;
  double timed = 0, passes = 0, in_tiles = 0, span = 0;
  for (auto _ : state) {
    RenderResult r = render(scene(), *sampler, o);
    state.SetIterationTime(r.stats.seconds - r.stats.build_seconds);
    timed += r.stats.seconds - r.stats.build_seconds, passes += r.stats.passes_seconds;
    in_tiles += r.stats.ranks.front().tile_seconds, span += r.stats.threads * r.stats.passes_seconds;
    total += r.stats.rays;
  }
  state.SetItemsProcessed(total);
  state.counters["passes_share"] = timed > 0 ? passes / timed : 0;
  // The workers' thread-seconds inside tiles over threads x the passes' time.
  state.counters["threads_busy"] = span > 0 ? in_tiles / span : 0;
}

}  // namespace

BENCHMARK(BM_RawEmbreePrimaryShadow)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_PdrtRenderDirect)->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(2.0);
