#include "renderer/render/lights/area_emitter.h"

namespace pdrt {

namespace {

int radiance_texture(const Material& m) {
  for (const TextureBinding& b : m.textures)
    if (b.param == MaterialParam::Radiance) return b.texture;
  return -1;
}

}  // namespace

Vec3 emitter_radiance(const EmbreeScene& scene, const TextureSet& textures, const Material& m, SurfaceHit h) {
  const int t = radiance_texture(m);
  if (t < 0) return m.radiance;
  scene.texture_coords(&h, 0);  // u, v do not depend on the time
  TextureCoords tc;
  tc.u = h.u, tc.v = h.v;  // a point lookup: a light sample is a point, not a pixel's footprint
  return emission(m.radiance, textures.eval(t, tc));
}

float emitter_luminance(const TextureSet& textures, const Material& m) {
  const int t = radiance_texture(m);
  if (t < 0) return luminance(m.radiance);
  double sum = 0;
  constexpr int n = 32;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      TextureCoords tc;
      tc.u = (i + 0.5f) / n, tc.v = (j + 0.5f) / n;
      sum += luminance(emission(m.radiance, textures.eval(t, tc)));
    }
  return float(sum / (n * n));
}

}  // namespace pdrt
