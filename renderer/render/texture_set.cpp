#include "renderer/render/texture_set.h"

#include "renderer/image/image_module.h"
#include "sampling/core/cache_dir.h"
#include "sampling/core/errors.h"

#include <algorithm>
#include <cmath>

namespace pdrt {

namespace {

int to_abi(TextureFilter f) {
  switch (f) {
    case TextureFilter::None:
      return PDRT_FILTER_NONE;
    case TextureFilter::Bilinear:
      return PDRT_FILTER_BILINEAR;
    case TextureFilter::Trilinear:
      return PDRT_FILTER_TRILINEAR;
    default:
      return PDRT_FILTER_EWA;
  }
}

int to_abi(TextureWrap w) {
  switch (w) {
    case TextureWrap::Clamp:
      return PDRT_WRAP_CLAMP;
    case TextureWrap::Black:
      return PDRT_WRAP_BLACK;
    case TextureWrap::Mirror:
      return PDRT_WRAP_MIRROR;
    default:
      return PDRT_WRAP_REPEAT;
  }
}

float unit(float x) { return x >= 0 ? (x <= 1 ? x : 1.0f) : 0.0f; }       // NaN -> 0
float non_negative(float x) { return x >= 0 && x < 3.0e38f ? x : 0.0f; }  // NaN, inf -> 0

// Brings a texture coordinate into one period of its wrap mode before OIIO converts it to an
// integer texel index (1e30 or inf would overflow int there); NaN and inf become 0.
float reduce(float x, TextureWrap w) {
  if (!std::isfinite(x)) return 0;
  switch (w) {
    case TextureWrap::Repeat:
      return std::abs(x) < 1e6f ? x : x - std::floor(x);
    case TextureWrap::Mirror:
      return std::abs(x) < 1e6f ? x : x - 2 * std::floor(x / 2);
    default:
      return std::clamp(x, -1.0f, 2.0f);
  }
}

}  // namespace

TextureSet::TextureSet(const SceneDesc& desc) : textures_(desc.textures), handles_(desc.textures.size(), nullptr) {
  for (size_t i = 0; i < textures_.size(); ++i) {
    const TextureDesc& t = textures_[i];
    if (t.kind != TextureDesc::Kind::Image) continue;
    const PdrtImageModule& m = image_module();
    char error[512] = "";
    if (!system_) {
      system_ = m.texture_system_create(error, sizeof error);
      if (!system_) throw InputError(std::string("cannot create a texture system: ") + error);
    }
    const std::string path = t.file.string(), cache = cache_dir().string();
    PdrtTextureOpen open{};
    open.path = path.c_str();
    open.cache_dir = cache.c_str();
    open.encoding = t.encoding == TextureEncoding::Srgb     ? PDRT_ENCODING_SRGB
                    : t.encoding == TextureEncoding::Linear ? PDRT_ENCODING_LINEAR
                                                            : PDRT_ENCODING_AUTO;
    if (m.texture_open(system_, &open, &handles_[i], error, sizeof error)) {
      m.texture_system_destroy(system_);  // the destructor does not run for a throwing constructor
      system_ = nullptr;
      throw InputError(t.where + ": cannot use " + path + " as a texture: " + error);
    }
  }
}

TextureSet::~TextureSet() {
  if (system_) image_module().texture_system_destroy(system_);
}

Vec3 TextureSet::lookup_image(const TextureDesc& t, int texture, const TextureCoords& tc) const {
  // Image rows run top to bottom, v bottom to top (OBJ, pbrt-v4): t = 1 - v.
  PdrtTextureLookup l;
  l.s = reduce(tc.u * t.scale_u, t.wrap), l.t = reduce(1 - tc.v * t.scale_v, t.wrap);
  auto d = [](float x) { return std::isfinite(x) ? std::clamp(x, -1e8f, 1e8f) : 0.0f; };
  l.dsdx = d(tc.dudx * t.scale_u), l.dtdx = d(-tc.dvdx * t.scale_v);
  l.dsdy = d(tc.dudy * t.scale_u), l.dtdy = d(-tc.dvdy * t.scale_v);
  l.filter = to_abi(t.filter), l.wrap = to_abi(t.wrap);
  float rgb[3];
  image_module().texture_lookup(system_, handles_[size_t(texture)], &l, rgb);
  return {rgb[0], rgb[1], rgb[2]};
}

Vec3 TextureSet::input(const TextureInput& in, const TextureCoords& tc) const {
  return in.texture < 0 ? in.value : eval(in.texture, tc);
}

Vec3 TextureSet::eval(int texture, const TextureCoords& tc) const {
  // A checkerboard picks one input, so it is a walk down the (acyclic) graph: a loop, however
  // long the chain. Scale, mix, invert and power recurse; the loaders bound how many such
  // nodes one evaluation visits (kMaxTextureEvaluation), and with it the recursion depth.
  for (;;) {
    const TextureDesc& t = textures_[size_t(texture)];
    switch (t.kind) {
      case TextureDesc::Kind::Constant:
        return t.value;
      case TextureDesc::Kind::Image:
        return lookup_image(t, texture, tc);
      case TextureDesc::Kind::Checkerboard: {
        // pbrt-v4 §10.5.1 (Checkerboard, point-sampled).
        const double cu = std::floor(double(tc.u) * t.scale_u), cv = std::floor(double(tc.v) * t.scale_v);
        const bool even = std::fmod(std::abs(cu + cv), 2.0) == 0;  // also false for NaN
        const TextureInput& in = even ? t.color0 : t.color1;
        if (in.texture < 0) return in.value;
        texture = in.texture;
        break;
      }
      case TextureDesc::Kind::Scale:  // pbrt-v4's ScaleTexture
        return input(t.tex, tc) * input(t.scale, tc);
      case TextureDesc::Kind::Mix: {  // pbrt-v4's MixTexture: amount is a float texture
        const float a = input(t.amount, tc).x;
        return input(t.tex1, tc) * (1 - a) + input(t.tex2, tc) * a;
      }
      case TextureDesc::Kind::Invert: {  // pbrt-v4's imagemap "invert": ClampZero(1 - x)
        const Vec3 x = input(t.tex, tc);
        return {std::max(0.0f, 1 - x.x), std::max(0.0f, 1 - x.y), std::max(0.0f, 1 - x.z)};
      }
      case TextureDesc::Kind::Power: {
        const Vec3 x = input(t.tex, tc);
        auto p = [&](float c) { return c > 0 ? std::pow(c, t.exponent) : 0.0f; };  // NaN -> 0
        return {p(x.x), p(x.y), p(x.z)};
      }
    }
  }
}

Material TextureSet::apply(Material out, const std::vector<TextureBinding>& bindings, const TextureCoords& tc) const {
  for (const TextureBinding& b : bindings) {
    const Vec3 x = eval(b.texture, tc);
    switch (b.param) {
      case MaterialParam::Albedo:
        out.albedo = Vec3(unit(x.x), unit(x.y), unit(x.z));
        break;
      case MaterialParam::Roughness:
        out.roughness = unit(x.x);
        break;
      case MaterialParam::CoatColor:
        out.coat_color = Vec3(unit(x.x), unit(x.y), unit(x.z));
        break;
      case MaterialParam::Radiance:
        out.radiance = emission(out.radiance, x);
        break;
      case MaterialParam::Amount:
        out.amount = unit(x.x);
        break;
      case MaterialParam::Reflectance:
        conductor_from_reflectance(Vec3(unit(x.x), unit(x.y), unit(x.z)), &out);
        break;
      case MaterialParam::BaseRoughness:
        out.base_roughness = unit(x.x);
        break;
    }
  }
  return out;
}

Vec3 emission(const Vec3& scale, const Vec3& texel) {
  return {scale.x * non_negative(texel.x), scale.y * non_negative(texel.y), scale.z * non_negative(texel.z)};
}

}  // namespace pdrt
