#include "renderer/scene/pbrt/pbrt_build_context.h"

#include "renderer/scene/text_file.h"

#include <cmath>

namespace pdrt {
namespace {

// Texture "imagemap": the file (relative to the including file), its filter, wrap and encoding;
// pbrt-v4's scale and invert become textures over the image.
void image_texture(PbrtBuild& b, const PbrtDirective& d, TextureDesc& t) {
  const PbrtParams& ps = d.params;
  t.kind = TextureDesc::Kind::Image;
  std::optional<std::string> name = ps.find_string("filename");
  if (!name) b.fail(d.at, "Texture \"imagemap\" needs \"string filename\"");
  const std::filesystem::path rel =
      d.at.file ? std::filesystem::path(*d.at.file).parent_path() : std::filesystem::path();
  t.file = std::filesystem::path(*name).is_absolute() ? std::filesystem::path(*name) : rel / *name;
  std::string reason;
  if (!can_open_file(t.file, reason))
    b.fail(ps.find("filename")->at, "cannot open \"" + t.file.string() + "\": " + reason);
  const std::string filter = ps.get_string("filter", "bilinear");
  if (filter == "point")
    t.filter = TextureFilter::None;
  else if (filter == "bilinear")
    t.filter = TextureFilter::Bilinear;
  else if (filter == "trilinear")
    t.filter = TextureFilter::Trilinear;
  else if (filter == "ewa")
    t.filter = TextureFilter::Ewa;
  else
    b.fail(ps.find("filter")->at, "unknown filter \"" + filter + "\" (point, bilinear, trilinear, ewa)");
  const std::string wrap = ps.get_string("wrap", "repeat");
  if (wrap == "repeat")
    t.wrap = TextureWrap::Repeat;
  else if (wrap == "black")
    t.wrap = TextureWrap::Black;
  else if (wrap == "clamp")
    t.wrap = TextureWrap::Clamp;
  else {
    b.note(ps.find("wrap")->at, "wrap \"" + wrap + "\" is not supported (repeat used)");
  }
  if (std::optional<std::string> enc = ps.find_string("encoding")) {
    if (*enc == "sRGB")
      t.encoding = TextureEncoding::Srgb;
    else if (*enc == "linear")
      t.encoding = TextureEncoding::Linear;
    else
      b.note(ps.find("encoding")->at, "encoding \"" + *enc + "\" is not supported (sRGB for 8-bit files, else linear)");
  }
  // pbrt-v4's image textures: ClampZero(invert ? 1 - scale x : scale x), as a scale and an
  // invert texture on top of the image (the name then means the outermost).
  const double scale = ps.get_float("scale", 1);
  if (!(scale >= 0) || !std::isfinite(scale))
    b.fail(ps.find("scale")->at, "\"float scale\" must be >= 0, got " + pbrt_number(scale));
  const bool invert = ps.get_bool("invert", false);
  if (scale != 1 || invert) {
    TextureInput in;
    in.texture = b.add_texture(std::move(t), d.strings[0] + " (image)", d.at);
    t = TextureDesc{};
    t.name = d.strings[0], t.where = d.at.str();
    if (scale != 1) {
      t.kind = TextureDesc::Kind::Scale;
      t.tex = in, t.scale.value = Vec3(float(scale));
      if (invert) {
        in.texture = b.add_texture(std::move(t), d.strings[0] + " (scaled image)", d.at);
        t = TextureDesc{};
        t.name = d.strings[0], t.where = d.at.str();
      }
    }
    if (invert) t.kind = TextureDesc::Kind::Invert, t.tex = in;
  }
}

}  // namespace

// pbrt-v4's texture classes as pdrt's: constant, checkerboard, imagemap (with its scale and
// invert as textures over it), scale and mix; any other class is reported and its materials
// get their default value.
void translate_pbrt_texture(PbrtBuild& b, const PbrtDirective& d) {
  const PbrtParams& ps = d.params;
  const std::string &kind = d.strings[1], &cls = d.strings[2];
  if (kind != "float" && kind != "spectrum")
    b.fail(d.at, "a texture's type must be \"float\" or \"spectrum\", got \"" + kind + "\"");
  const std::string key = kind + ":" + d.strings[0];
  TextureDesc t;
  t.name = d.strings[0];
  t.where = d.at.str();
  bool supported = true;
  if (const std::optional<std::string> mapping = ps.find_string("mapping"); mapping && *mapping != "uv") {
    b.note(ps.find("mapping")->at, "texture mapping \"" + *mapping + "\" is not supported (skipped)");
    supported = false;
  }
  t.scale_u = float(ps.get_float("uscale", 1)), t.scale_v = float(ps.get_float("vscale", 1));
  if (!(t.scale_u > 0 && t.scale_v > 0)) b.fail(d.at, "\"uscale\" and \"vscale\" must be > 0");
  for (const char* k : {"udelta", "vdelta"})
    if (ps.get_float(k, 0) != 0) b.note(ps.find(k)->at, std::string("\"") + k + "\" is not supported (0 used)");
  // pbrt-v4's ScaleTexture and MixTexture (their inputs come before them: no cycles).
  auto non_negative = [&](const char* name, float fallback) {
    TextureInput in = b.texture_input(ps, name, fallback, kind);
    for (int c = 0; c < 3; ++c)
      if (!(in.value[c] >= 0))
        b.fail(ps.find(name)->at, std::string("\"") + name + "\" must be >= 0, got " + pbrt_number(in.value[c]));
    return in;
  };
  if (cls == "scale") {
    t.kind = TextureDesc::Kind::Scale;
    t.tex = non_negative("tex", 1);
    t.scale = non_negative("scale", 1);
  } else if (cls == "mix") {
    t.kind = TextureDesc::Kind::Mix;
    t.tex1 = non_negative("tex1", 0);
    t.tex2 = non_negative("tex2", 1);
    t.amount = b.texture_input(ps, "amount", 0.5f, "float");
  } else if (cls == "constant") {
    t.kind = TextureDesc::Kind::Constant;
    t.value = b.color(ps, "value", Vec3(1.0f), false);
  } else if (cls == "checkerboard") {
    t.kind = TextureDesc::Kind::Checkerboard;
    if (ps.get_int("dimension", 2) != 2) {
      b.note(d.at, "3-D checkerboards are not supported (skipped)");
      supported = false;
    }
    t.color0 = b.texture_input(ps, "tex1", 1, kind);
    t.color1 = b.texture_input(ps, "tex2", 0, kind);
  } else if (cls == "imagemap") {
    image_texture(b, d, t);
    if (kind == "spectrum")
      b.note_rgb(d.at, "spectrum image texture \"" + t.name + "\" where its colours are not grey");
  } else {
    b.note(d.at, "Texture class \"" + cls + "\" is not supported (materials using it get their default value)");
    supported = false;
  }
  if (!supported) {
    for (const PbrtParam& p : ps.list) p.used = true;
    b.textures[key] = -1;
    return;
  }
  const std::string name = t.name;
  b.textures[key] = b.add_texture(std::move(t), name, d.at);
}

}  // namespace pdrt
