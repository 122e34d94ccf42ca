#pragma once
// The scene's textures, ready to evaluate at a hit (docs/renderer.md, "Textures"):
//   constant      its value
//   checkerboard  pbrt-v4's 2-D checkerboard, point-evaluated (no filtering, so it aliases):
//                 color0 where floor(u su) + floor(v sv) is even, else color1
//   image         OpenImageIO's TextureSystem inside the image module (image_module_abi.h),
//                 on a linear-float MIP-mapped copy; filter none = the nearest texel
//   scale, mix, invert, power   per channel from their inputs (texture_desc.h)
// Material parameters bound to textures (Material::textures) are overridden per hit: colours
// clamped to [0, 1] per channel, scalars (roughness, a mix's amount) the first channel clamped
// to [0, 1]; a conductor's reflectance sets eta and k (conductor_from_reflectance);
// NaN becomes 0. Thread-safe after construction.
#include "renderer/render/texture_footprint.h"
#include "renderer/scene/scene_desc.h"

#include <vector>

namespace pdrt {

// An emitter's radiance where `radiance` is bound to a texture: the texel (each channel >= 0,
// unbounded: an EXR may hold HDR values; NaN and inf become 0) times the material's `radiance`,
// which then holds the scene's `scale`.
Vec3 emission(const Vec3& scale, const Vec3& texel);

class TextureSet {
 public:
  // Opens every image texture (throws InputError naming the texture's `file` key when an
  // image cannot be read or converted). Loads the image module only if there is one.
  explicit TextureSet(const SceneDesc& desc);
  ~TextureSet();
  TextureSet(const TextureSet&) = delete;
  TextureSet& operator=(const TextureSet&) = delete;

  Vec3 eval(int texture, const TextureCoords& tc) const;
  // `m` with the parameters `bindings` name evaluated at tc. Pass m without name and
  // textures (PathIntegrator keeps such copies) so that the copy allocates nothing.
  Material apply(Material m, const std::vector<TextureBinding>& bindings, const TextureCoords& tc) const;

 private:
  Vec3 input(const TextureInput& in, const TextureCoords& tc) const;
  Vec3 lookup_image(const TextureDesc& t, int texture, const TextureCoords& tc) const;

  std::vector<TextureDesc> textures_;
  void* system_ = nullptr;      // the module's TextureSystem, when there are images
  std::vector<void*> handles_;  // per texture: its image handle, or null
};

}  // namespace pdrt
