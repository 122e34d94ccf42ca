// Issue 4 speed target: on a >= 500k-triangle scene, pdrt's rays per second (primary +
// shadow, max_depth 1) against raw rtcIntersect1 + rtcOccluded1 throughput on the same
// scene, camera, resolution and threads. Both report rays/s as items_per_second.
#include "renderer/render/embree_scene.h"
#include "renderer/render/renderer.h"
#include "sampling/core/rng.h"
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
// occlusion ray toward a hashed direction of the upper hemisphere.
void BM_RawEmbreePrimaryShadow(benchmark::State& state) {
  EmbreeDevice device;
  EmbreeScene es(scene(), device);
  ThinLensCamera cam(scene().camera, kW, kH);
  int64_t total = 0;
  for (auto _ : state) {
    tbb::enumerable_thread_specific<int64_t> rays(0);
    tbb::parallel_for(tbb::blocked_range<int>(0, kH), [&](const tbb::blocked_range<int>& r) {
      int64_t& n = rays.local();
      RTCIntersectContext ctx;
      for (int y = r.begin(); y != r.end(); ++y)
        for (int x = 0; x < kW; ++x)
          for (int s = 0; s < kSpp; ++s) {
            uint64_t h = mix64(uint64_t(y) * kW * kSpp + x * kSpp + s);
            Ray ray = cam.generate(x + (h & 0xffff) / 65536.0f, y + ((h >> 16) & 0xffff) / 65536.0f, {0.5, 0.5}, 0);
            RTCRayHit rh;
            rh.ray.org_x = ray.org.x, rh.ray.org_y = ray.org.y, rh.ray.org_z = ray.org.z;
            rh.ray.dir_x = ray.dir.x, rh.ray.dir_y = ray.dir.y, rh.ray.dir_z = ray.dir.z;
            rh.ray.tnear = 0, rh.ray.tfar = 1e30f, rh.ray.time = 0, rh.ray.mask = ~0u, rh.ray.flags = 0;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID, rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcInitIntersectContext(&ctx);
            rtcIntersect1(es.rtc_scene(), &ctx, &rh);
            ++n;
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
            float t = rh.ray.tfar;
            Vec3 p = ray.org + ray.dir * t;
            float u = ((h >> 32) & 0xffff) / 65536.0f, v = ((h >> 48) & 0xffff) / 65536.0f;
            float z = u, rr = std::sqrt(1 - z * z), ph = 2 * kPi * v;
            Vec3 d(rr * std::cos(ph), z, rr * std::sin(ph));
            Vec3 o = p + Vec3(0, 1e-3f, 0);
            RTCRay sr;
            sr.org_x = o.x, sr.org_y = o.y, sr.org_z = o.z, sr.dir_x = d.x, sr.dir_y = d.y, sr.dir_z = d.z;
            sr.tnear = 0, sr.tfar = 1e30f, sr.time = 0, sr.mask = ~0u, sr.flags = 0;
            rtcInitIntersectContext(&ctx);
            rtcOccluded1(es.rtc_scene(), &ctx, &sr);
            ++n;
          }
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
  for (auto _ : state) {
    RenderResult r = render(scene(), *sampler, o);
    state.SetIterationTime(r.stats.seconds - r.stats.build_seconds);
    total += r.stats.rays;
  }
  state.SetItemsProcessed(total);
}

}  // namespace

BENCHMARK(BM_RawEmbreePrimaryShadow)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
BENCHMARK(BM_PdrtRenderDirect)->Unit(benchmark::kMillisecond)->UseManualTime()->MinTime(2.0);
