#pragma once
// Textures as the scene file describes them ("textures", docs/scene-format.md): named, and
// referred to by name from material parameters and from other textures (pbrt-v4's texture
// graph, without cycles). Evaluation lives in render/texture_set.h.
#include "renderer/scene/vec3.h"

#include <filesystem>
#include <string>

namespace pdrt {

// A constant value or another texture (texture >= 0: its index in SceneDesc::textures).
struct TextureInput {
  Vec3 value{0.0f};
  int texture = -1;
};

enum class TextureFilter { None, Bilinear, Trilinear, Ewa };  // None: the nearest texel, no MIP
enum class TextureWrap { Repeat, Clamp, Black, Mirror };
enum class TextureEncoding { Auto, Srgb, Linear };  // Auto: sRGB for 8/16-bit integer files

struct TextureDesc {
  enum class Kind { Constant, Checkerboard, Image } kind = Kind::Constant;
  std::string name;
  std::string where;        // "scene.json:12:5: textures.checks" for messages raised later
  Vec3 value{0.0f};         // Constant
  float scale_u = 1, scale_v = 1;  // Checkerboard: checks per unit uv; Image: repeats per unit uv
  TextureInput color0, color1;     // Checkerboard: even and odd checks
  std::filesystem::path file;      // Image, resolved against the scene's directory
  TextureFilter filter = TextureFilter::Bilinear;
  TextureWrap wrap = TextureWrap::Repeat;
  TextureEncoding encoding = TextureEncoding::Auto;
};

}  // namespace pdrt
