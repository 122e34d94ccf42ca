#include "renderer/scene/pbrt/pbrt_build_context.h"

#include "renderer/scene/environment_image.h"
#include "renderer/scene/pbrt/equal_area_octahedral.h"
#include "renderer/scene/pbrt/pbrt_spectrum.h"

#include <algorithm>
#include <cmath>

// pbrt-v4's lights as pdrt's: point, spot, distant and infinite (constant or an image) light
// sources, and the diffuse area light the shapes that follow emit with.

namespace pdrt {
namespace {

// An infinite light with an image: pbrt-v4's equal-area octahedral square, resampled into
// pdrt's equirectangular environment (equal_area_octahedral.h).
// A `power` or `illuminance`: pbrt-v4 applies it only when > 0 (its default -1 means unset);
// a non-finite value is an error.
std::optional<double> positive_or_unset(PbrtBuild& b, const PbrtParams& ps, const char* name) {
  std::optional<double> v = ps.find_float(name);
  if (!v) return std::nullopt;
  if (!std::isfinite(*v))
    b.fail(ps.find(name)->at, std::string("\"float ") + name + "\" must be finite, got " + pbrt_number(*v));
  return *v > 0 ? v : std::nullopt;
}

void image_light(PbrtBuild& b, const PbrtDirective& d, float scale) {
  const PbrtParams& ps = d.params;
  const PbrtParam& f = *ps.find("filename");
  const std::string name = *ps.find_string("filename");
  if (ps.find("L")) b.fail(ps.find("L")->at, "an infinite light takes \"L\" or \"filename\", not both");
  const std::filesystem::path rel =
      d.at.file ? std::filesystem::path(*d.at.file).parent_path() : std::filesystem::path();
  const std::filesystem::path file =
      std::filesystem::path(name).is_absolute() ? std::filesystem::path(name) : rel / name;
  EnvironmentImage img;
  std::string reason;
  if (!read_environment_image(file, &img, &reason)) b.fail(f.at, "cannot read \"" + name + "\": " + reason);
  if (img.width != img.height)
    b.fail(f.at, "\"" + name + "\" is " + std::to_string(img.width) + " x " + std::to_string(img.height) +
                     ": pbrt-v4's environment images are square (equal-area octahedral)");
  for (float v : img.rgb)
    if (!(std::isfinite(v) && v >= 0)) b.fail(f.at, "\"" + name + "\" holds a negative or non-finite value");
  if (!b.gs.cur.ctm.t[0].affine()) b.fail(d.at, "the current transform is projective");
  if (b.gs.moving()) b.note(d.at, "a moving infinite light is not supported (its start orientation is used)");
  const std::optional<Mat4> inv = b.gs.cur.ctm.t[0].inverse();
  if (!inv) b.fail(d.at, "the current transform is singular");
  double e_v = 0;
  if (auto e = positive_or_unset(b, ps, "illuminance")) {
    // pbrt-v4: scale so the upper hemisphere (light space +z) gives illuminance e; every
    // texel of the equal-area square subtends 4 pi / n^2.
    double sum = 0;
    const int n = img.width;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Vec3 w = equal_area_square_to_sphere((x + 0.5) / n, (y + 0.5) / n);
        const float* p = &img.rgb[3 * (size_t(y) * size_t(n) + size_t(x))];
        if (w.z > 0) sum += luminance(Vec3(p[0], p[1], p[2])) * w.z;
      }
    e_v = sum * 4 * kPbrtPi / (double(n) * n);
    if (e_v > 0) scale *= float(*e / e_v);
  }
  b.note(f.at, "\"" + name +
                   "\" is resampled to pdrt's equirectangular map and interpolated, where pbrt-v4 shows its nearest "
                   "texel: texel edges seen directly are soft");
  const Mat4 to_light = *inv;
  EnvironmentImage eq = octahedral_to_equirect(img, [&](const Vec3& w) { return to_light.vector(w); });
  EnvironmentDesc& env = b.out.scene.environment;
  env.file = file.string();
  env.width = eq.width, env.height = eq.height;
  env.rgb = std::move(eq.rgb);
  env.scale = Vec3(scale);
  env.resampled = true;
}

void light(PbrtBuild& b, const PbrtDirective& d) {
  const PbrtParams& ps = d.params;
  const std::string& t = d.strings[0];
  const float scale = float(ps.get_float("scale", 1));
  if (!(scale >= 0) || !std::isfinite(scale)) b.fail(d.at, "\"float scale\" must be >= 0");
  if (t == "point" || t == "spot") {
    DeltaLightDesc l;
    l.kind = t == "point" ? DeltaLightDesc::Kind::Point : DeltaLightDesc::Kind::Spot;
    Vec3 I = b.color(ps, "I", Vec3(1.0f), true) * scale;
    std::vector<Vec3> from = ps.point3s("from");
    l.position = from.empty() ? Vec3(0.0f) : from[0];
    if (t == "spot") {
      std::vector<Vec3> to = ps.point3s("to");
      const Vec3 target = to.empty() ? Vec3(0, 0, 1) : to[0];
      if (length(target - l.position) == 0) b.fail(d.at, "a spot light needs \"to\" different from \"from\"");
      l.direction = normalize(target - l.position);
      const double cone = ps.get_float("coneangle", 30), delta = ps.get_float("conedeltaangle", 5);
      if (!(cone > 0 && cone <= 180)) b.fail(d.at, "\"float coneangle\" must be in (0, 180], got " + pbrt_number(cone));
      l.cos_cone = float(std::cos(cone * kPbrtPi / 180));
      l.cos_falloff_start = float(std::cos(std::clamp(cone - delta, 0.0, cone) * kPbrtPi / 180));
    }
    if (auto power = positive_or_unset(b, ps, "power")) {
      // pbrt-v4 (PointLight/SpotLight::Create): scale *= power / k_e, k_e = 4 pi for a point
      // light, a spot light's cone integral; the spectrum was already divided by its
      // illuminant's photometric value (color()), never by the RGB colour's luminance.
      const double solid = t == "point" ? 4 * kPbrtPi : 2 * kPbrtPi * (1 - 0.5 * (l.cos_cone + l.cos_falloff_start));
      I = I * float(*power / solid);
    }
    l.intensity = I;
    b.place(d.at, &l.transform, &l.motion);
    b.out.scene.delta_lights.push_back(l);
    return;
  }
  if (t == "distant") {
    DeltaLightDesc l;
    l.kind = DeltaLightDesc::Kind::Distant;
    Vec3 L = b.color(ps, "L", Vec3(1.0f), true) * scale;
    std::vector<Vec3> from = ps.point3s("from"), to = ps.point3s("to");
    const Vec3 f = from.empty() ? Vec3(0.0f) : from[0], g = to.empty() ? Vec3(0, 0, 1) : to[0];
    if (length(g - f) == 0) b.fail(d.at, "a distant light needs \"to\" different from \"from\"");
    if (b.gs.moving()) b.note(d.at, "a moving distant light is not supported (its start direction is used)");
    if (!b.gs.cur.ctm.t[0].affine()) b.fail(d.at, "the current transform is projective");
    const Vec3 travel = b.gs.cur.ctm.t[0].vector(g - f);
    if (!(length(travel) > 0)) b.fail(d.at, "the current transform collapses the light's direction");
    l.direction = normalize(travel);
    if (auto e = positive_or_unset(b, ps, "illuminance")) L = L * float(*e);  // pbrt-v4: scale *= E_v
    l.irradiance = L;
    b.out.scene.delta_lights.push_back(l);
    return;
  }
  if (t == "infinite") {
    if (!is_black(b.out.scene.environment.radiance) || b.out.scene.environment.has_map()) {
      b.note(d.at, "a second infinite light is not supported (skipped)");
      for (const PbrtParam& p : ps.list) p.used = true;
      return;
    }
    if (ps.find("filename")) return image_light(b, d, scale);
    Vec3 L = b.color(ps, "L", Vec3(1.0f), true) * scale;
    // pbrt-v4: scale *= E_v / pi, the illuminance of the upper hemisphere per unit radiance.
    if (auto e = positive_or_unset(b, ps, "illuminance")) L = L * float(*e / kPbrtPi);
    b.out.scene.environment.radiance = L;
    return;
  }
  b.note(d.at, "LightSource \"" + t + "\" is not supported (skipped)");
  for (const PbrtParam& p : ps.list) p.used = true;
}

// AreaLightSource "diffuse": the shapes that follow emit L * scale.
void area_light(PbrtBuild& b, const PbrtDirective& d) {
  if (d.strings[0] != "diffuse") {
    b.note(d.at, "AreaLightSource \"" + d.strings[0] + "\" is not supported (no emission)");
    for (const PbrtParam& p : d.params.list) p.used = true;
    b.gs.cur.area.reset();
    return;
  }
  PbrtAreaLight l;
  l.at = d.at;
  Vec3 L = b.color(d.params, "L", Vec3(1.0f), true);
  float scale = float(d.params.get_float("scale", 1));
  if (!(scale >= 0)) b.fail(d.at, "\"float scale\" must be >= 0");
  l.power = positive_or_unset(b, d.params, "power");
  l.radiance = L * scale;
  l.two_sided = d.params.get_bool("twosided", false);
  b.gs.cur.area = l;
}

}  // namespace

void translate_pbrt_light(PbrtBuild& b, const PbrtDirective& d) {
  switch (d.kind) {
    case PbrtDirectiveKind::LightSource:
      return light(b, d);
    case PbrtDirectiveKind::AreaLightSource:
      return area_light(b, d);
    default:
      b.fail(d.at, "directive " + d.name + " is not a light");
  }
}

}  // namespace pdrt
