#pragma once
// Raw Embree on the benchmark scene: one rtcIntersect1 / rtcOccluded1 per ray, no shading, the
// rays pdrt's own would be compared with (bench_render, thread_scaling). Each function traces
// a range of work items and returns the rays it traced; callers spread ranges over TBB threads.
#include "renderer/render/embree_scene.h"
#include "renderer/render/thin_lens_camera.h"
#include "sampling/core/rng.h"

#include <cmath>
#include <cstdint>

namespace pdrt::bench {

inline RTCRayHit ray_hit(const Vec3& o, const Vec3& d) {
  RTCRayHit rh;
  rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z;
  rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z;
  rh.ray.tnear = 0, rh.ray.tfar = 1e30f, rh.ray.time = 0, rh.ray.mask = ~0u, rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID, rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// A direction uniform on the upper hemisphere (y up) from two 16-bit fractions.
inline Vec3 upper_direction(uint64_t bits) {
  const float z = (bits & 0xffff) / 65536.0f, v = ((bits >> 16) & 0xffff) / 65536.0f;
  const float r = std::sqrt(1 - z * z), phi = 2 * kPi * v;
  return Vec3(r * std::cos(phi), z, r * std::sin(phi));
}

// Rows [y0, y1) of a width-wide image at spp samples per pixel: one camera ray per sample
// through a hashed position in the pixel (coherent: neighbours follow each other), and with
// `shadow` on a hit one occlusion ray toward a hashed direction of the upper hemisphere.
inline int64_t trace_camera_rows(const EmbreeScene& es, const ThinLensCamera& cam, int width, int spp, int y0, int y1,
                                 bool shadow) {
  int64_t n = 0;
  RTCIntersectContext ctx;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < width; ++x)
      for (int s = 0; s < spp; ++s) {
        const uint64_t h = mix64(uint64_t(y) * width * spp + uint64_t(x) * spp + s);
        const Ray ray = cam.generate(x + (h & 0xffff) / 65536.0f, y + ((h >> 16) & 0xffff) / 65536.0f, {0.5, 0.5}, 0);
        RTCRayHit rh = ray_hit(ray.org, ray.dir);
        rtcInitIntersectContext(&ctx);
        rtcIntersect1(es.rtc_scene(), &ctx, &rh);
        ++n;
        if (!shadow || rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        const Vec3 o = ray.org + ray.dir * rh.ray.tfar + Vec3(0, 1e-3f, 0), d = upper_direction(h >> 32);
        RTCRay sr = ray_hit(o, d).ray;
        rtcInitIntersectContext(&ctx);
        rtcOccluded1(es.rtc_scene(), &ctx, &sr);
        ++n;
      }
  return n;
}

// Rays [first, last) of an incoherent set: each from a hashed point of the box |x|, |z| < 2,
// 0 < y < 2.5 (around the sphere, above the ground) toward a hashed direction of the sphere,
// so neither origins nor directions of consecutive rays are related.
inline int64_t trace_incoherent(const EmbreeScene& es, uint64_t first, uint64_t last) {
  RTCIntersectContext ctx;
  for (uint64_t i = first; i < last; ++i) {
    const uint64_t a = mix64(i * 2 + 1), b = mix64(i * 2 + 2);
    const Vec3 o(4 * ((a & 0xffff) / 65536.0f) - 2, 2.5f * (((a >> 16) & 0xffff) / 65536.0f),
                 4 * (((a >> 32) & 0xffff) / 65536.0f) - 2);
    Vec3 d = upper_direction(b);
    if ((b >> 40) & 1) d.y = -d.y;
    RTCRayHit rh = ray_hit(o, d);
    rtcInitIntersectContext(&ctx);
    rtcIntersect1(es.rtc_scene(), &ctx, &rh);
  }
  return int64_t(last - first);
}

}  // namespace pdrt::bench
