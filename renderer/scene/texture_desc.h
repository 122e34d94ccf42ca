#pragma once
// Textures as the scene file describes them ("textures", docs/scene-format.md): named, and
// referred to by name from material parameters and from other textures (pbrt-v4's texture
// graph, without cycles). Evaluation lives in render/texture_set.h.
#include "renderer/scene/vec3.h"

#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

// A constant value or another texture (texture >= 0: its index in SceneDesc::textures).
struct TextureInput {
  Vec3 value{0.0f};
  int texture = -1;
};

enum class TextureFilter { None, Bilinear, Trilinear, Ewa };  // None: the nearest texel, no MIP
enum class TextureWrap { Repeat, Clamp, Black, Mirror };
enum class TextureEncoding { Auto, Srgb, Linear };  // Auto: sRGB for 8/16-bit integer files

// Kinds that combine other textures (render/texture_set.h evaluates them):
//   Scale   tex * scale per channel (pbrt-v4's ScaleTexture)
//   Mix     (1 - a) tex1 + a tex2, a the first channel of amount (pbrt-v4's MixTexture)
//   Invert  max(0, 1 - tex) per channel (pbrt-v4's imagemap "invert")
//   Power   max(0, tex)^exponent per channel: pbrt roughness textures as pdrt's perceptual
//           roughness (alpha = roughness^2), e.g. exponent 1/4 under remaproughness
struct TextureDesc {
  enum class Kind { Constant, Checkerboard, Image, Scale, Mix, Invert, Power } kind = Kind::Constant;
  std::string name;
  std::string where;               // "scene.json:12:5: textures.checks" for messages raised later
  Vec3 value{0.0f};                // Constant
  float scale_u = 1, scale_v = 1;  // Checkerboard: checks per unit uv; Image: repeats per unit uv
  TextureInput color0, color1;     // Checkerboard: even and odd checks
  std::filesystem::path file;      // Image, resolved against the scene's directory
  TextureFilter filter = TextureFilter::Bilinear;
  TextureWrap wrap = TextureWrap::Repeat;
  TextureEncoding encoding = TextureEncoding::Auto;
  TextureInput tex{Vec3(1.0f)}, scale{Vec3(1.0f)};                      // Scale; Invert and Power use tex
  TextureInput tex1{Vec3(0.0f)}, tex2{Vec3(1.0f)}, amount{Vec3(0.5f)};  // Mix
  float exponent = 1;                                                   // Power
};

// The texture's inputs that are textures (for graph checks and writers).
std::vector<int> texture_inputs(const TextureDesc& t);

// Evaluating texture t visits at most this many Scale, Mix, Invert and Power nodes (a mix
// of two mixes of the same texture doubles the work per level): the loaders refuse more, so
// that recursion depth and time per lookup stay bounded whatever a scene file says.
inline constexpr int kMaxTextureEvaluation = 1024;
// The node count above for every texture, given that each texture's inputs come before it in
// `order` (a topological order; pass an empty order for "by index", as the pbrt importer builds).
std::vector<long long> texture_evaluation_cost(const std::vector<TextureDesc>& textures, const std::vector<int>& order);
// The same for one texture, given the costs of its inputs (indexed like SceneDesc::textures).
long long texture_node_cost(const TextureDesc& t, const std::vector<long long>& cost);

}  // namespace pdrt
