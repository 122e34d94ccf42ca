#include "renderer/scene/pbrt/pbrt_build_context.h"

#include "renderer/scene/crop_window.h"
#include "renderer/scene/render_settings.h"
#include "sampling/core/errors.h"
#include "sampling/samplers/sampler_names.h"

#include <algorithm>
#include <cmath>

// The rendering options: Camera, Film, PixelFilter, Sampler, Integrator.

namespace pdrt {
namespace {

// pbrt-v4 CameraBase: "screenwindow" [x0 x1 y0 y1] in screen space and "frameaspectratio",
// resolved against the film in resolve_screen(b) once its resolution is known.
void screen_params(PbrtBuild& b, const PbrtParams& ps) {
  if (const PbrtParam* p = ps.find("screenwindow")) {
    std::vector<double> w = ps.floats("screenwindow");
    p->used = true;
    if (w.size() != 4)
      b.fail(p->at, "\"float screenwindow\" needs 4 values [x0 x1 y0 y1], got " + std::to_string(w.size()));
    for (double v : w)
      if (!(std::abs(v) <= 1e6))
        b.fail(p->at, "\"float screenwindow\" values must be finite, within [-1e6, 1e6], got " + pbrt_number(v));
    if (!(w[0] < w[1] && w[2] < w[3])) b.fail(p->at, "\"float screenwindow\" must have x0 < x1 and y0 < y1");
    b.camera.screen_window = {float(w[0]), float(w[1]), float(w[2]), float(w[3])};
  }
  if (ps.find("frameaspectratio")) b.camera.frame_aspect = b.positive(ps, "frameaspectratio", 1);
}

void camera(PbrtBuild& b, const PbrtDirective& d, const PbrtTransformPair& camera_from_world, bool implicit = false) {
  if (b.camera.seen) b.fail(d.at, "a second Camera");
  if (b.gs.in_world && !implicit) b.fail(d.at, "Camera must come before WorldBegin");
  b.camera.seen = true;
  b.gs.named["camera"] = camera_from_world;
  CameraDesc& c = b.out.scene.camera;
  const PbrtParams& ps = d.params;
  if (d.strings[0] == "orthographic") {
    c.projection = CameraDesc::Projection::Orthographic;
    if (ps.get_float("lensradius", 0) > 0)
      b.note(ps.find("lensradius")->at,
             "orthographic depth of field moves each ray's own origin by the lens offset "
             "(pbrt-v4 starts every ray at the lens offset from the camera's centre, "
             "mmp/pbrt-v3#315): out-of-focus blur differs");
  } else if (d.strings[0] != "perspective") {
    b.note(d.at, "Camera \"" + d.strings[0] + "\" is not supported (a perspective camera is used)");
    for (const PbrtParam& p : ps.list) p.used = true;
  }
  Mat4 world_from_camera[2];
  for (int i = 0; i < 2; ++i) {
    auto inv = camera_from_world.t[i].inverse();
    if (!inv || !inv->affine()) b.fail(d.at, "the camera transform is singular or projective");
    world_from_camera[i] = *inv;
  }
  auto pose = [&](const Mat4& w, Vec3* pos, Vec3* fwd, Vec3* up, Vec3* right) {
    *pos = w.point({0, 0, 0});
    *fwd = normalize(w.vector({0, 0, 1}));
    *up = normalize(w.vector({0, 1, 0}));
    *right = w.vector({1, 0, 0});
  };
  Vec3 pos, fwd, up, right;
  pose(world_from_camera[0], &pos, &fwd, &up, &right);
  // Camera-space lengths in scene units: the orthographic screen window is in camera space.
  b.camera.scale = {length(right), length(world_from_camera[0].vector({0, 1, 0}))};
  c.position = pos;
  c.up = up;
  // pbrt's raster x follows camera +x; pdrt's follows forward x up unless flipped.
  c.flip_x = dot(right, cross(fwd, up)) < 0;
  const float focal = b.positive(ps, "focaldistance", 1e6f);
  c.look_at = pos + fwd;
  c.focus_distance = focal;
  c.aperture_radius = b.positive(ps, "lensradius", 0, true);
  float open = float(ps.get_float("shutteropen", 0)), close = float(ps.get_float("shutterclose", 1));
  if (!(open <= close)) b.fail(d.at, "shutteropen must be <= shutterclose");
  c.shutter_open = open, c.shutter_close = close;
  if (!(camera_from_world.t[0] == camera_from_world.t[1])) {
    Vec3 p1, f1, u1, r1;
    pose(world_from_camera[1], &p1, &f1, &u1, &r1);
    if (length(u1 - up) > 1e-4f)
      b.note(d.at, "the camera's up vector turns during the shutter (pdrt keeps the start's)");
    c.motion = {{float(b.gs.times[0]), pos, pos + fwd}, {float(b.gs.times[1]), p1, p1 + f1}};
    if (!(b.gs.times[0] >= open && b.gs.times[1] <= close) || b.gs.times[0] == b.gs.times[1]) {
      b.note(d.at, "camera motion keys at TransformTimes " + pbrt_number(b.gs.times[0]) + ", " +
                       pbrt_number(b.gs.times[1]) + " outside the shutter or at one time (camera motion dropped)");
      c.motion.clear();
    }
  }
  if (c.projection == CameraDesc::Projection::Perspective) {
    b.camera.fov = float(ps.get_float("fov", 90));
    if (!(b.camera.fov > 0 && b.camera.fov < 180))
      b.fail(ps.find("fov")->at, "\"float fov\" must be in (0, 180), got " + pbrt_number(b.camera.fov));
  }
  screen_params(b, ps);
  b.camera.at = d.at;
}

// pbrt-v4 FilmBaseParameters: "pixelbounds" [x0 x1 y0 y1] in pixels (each pair sorted,
// clamped to the film) or "cropwindow" [x0 x1 y0 y1] (each pair sorted, clamped to [0, 1];
// wins when both are given).
void crop(PbrtBuild& b, const PbrtParams& ps) {
  FilmDesc& f = b.out.scene.film;
  // A Film directive replaces the film (pbrt-v4): an earlier one's crop, in pixels of its
  // size, does not carry over.
  f.crop_window = FilmDesc{}.crop_window;
  const PbrtParam* cw = ps.find("cropwindow");
  const PbrtParam* pb = ps.find("pixelbounds");
  if (!cw && !pb) return;
  if (pb) {
    std::vector<int64_t> px = ps.ints("pixelbounds");
    pb->used = true;
    if (px.size() != 4)
      b.fail(pb->at, "\"integer pixelbounds\" needs 4 values [x0 x1 y0 y1], got " + std::to_string(px.size()));
    if (cw) b.note(pb->at, "both \"cropwindow\" and \"pixelbounds\" (the crop window used, as pbrt-v4)");
    auto clamp = [](int64_t v, int hi) { return int(std::clamp<int64_t>(v, 0, hi)); };
    f.crop_window = crop_window_for_pixels(
        clamp(std::min(px[0], px[1]), f.width), clamp(std::max(px[0], px[1]), f.width),
        clamp(std::min(px[2], px[3]), f.height), clamp(std::max(px[2], px[3]), f.height), f.width, f.height);
  }
  if (cw) {
    std::vector<double> c = ps.floats("cropwindow");
    cw->used = true;
    if (c.size() != 4)
      b.fail(cw->at, "\"float cropwindow\" needs 4 values [x0 x1 y0 y1], got " + std::to_string(c.size()));
    for (double v : c)
      if (!std::isfinite(v)) b.fail(cw->at, "\"float cropwindow\" values must be finite, got " + pbrt_number(v));
    auto unit = [](double v) { return float(std::clamp(v, 0.0, 1.0)); };
    f.crop_window = {unit(std::min(c[0], c[1])), unit(std::max(c[0], c[1])), unit(std::min(c[2], c[3])),
                     unit(std::max(c[2], c[3]))};
  }
  if (std::string p = crop_window_problem(f); !p.empty())
    b.fail((cw ? cw : pb)->at, std::string(cw ? "\"float cropwindow\" " : "\"integer pixelbounds\" ") + p);
}

void film(PbrtBuild& b, const PbrtDirective& d) {
  if (d.strings[0] != "rgb" && d.strings[0] != "gbuffer")
    b.note(d.at, "Film \"" + d.strings[0] + "\" is not supported (rgb used)");
  const PbrtParams& ps = d.params;
  auto res = [&](const char* name, int fallback) {
    std::optional<int64_t> v = ps.find_int(name);
    if (!v) return fallback;
    if (*v < 1 || *v > 65536)
      b.fail(ps.find(name)->at,
             std::string("\"integer ") + name + "\" must be in [1, 65536], got " + std::to_string(*v));
    return int(*v);
  };
  b.out.scene.film.width = res("xresolution", 1280);
  b.out.scene.film.height = res("yresolution", 720);
  if (const PbrtParam* p = ps.find("filename")) p->used = true;  // pdrt render -o names the output
  crop(b, ps);
  for (const char* k : {"iso", "exposuretime", "whitebalance"})
    if (const PbrtParam* p = ps.find(k)) {
      p->used = true;
      b.note(p->at, std::string("\"") + k + "\" is not supported (ignored)");
    }
}

void filter(PbrtBuild& b, const PbrtDirective& d) {
  FilterDesc& f = b.out.scene.film.filter;
  const std::string& t = d.strings[0];
  float def = 0.5f;
  if (t == "box")
    f.type = FilterType::Box, def = 0.5f;
  else if (t == "gaussian")
    f.type = FilterType::Gaussian, def = 1.5f;
  else if (t == "mitchell")
    f.type = FilterType::Mitchell, def = 2;
  else if (t == "triangle")
    f.type = FilterType::Tent, def = 2;
  else {
    b.note(d.at, "PixelFilter \"" + t + "\" is not supported (pbrt-v4's default gaussian used)");
    f.type = FilterType::Gaussian, def = 1.5f;
    for (const PbrtParam& p : d.params.list) p.used = true;
  }
  const float rx = b.positive(d.params, "xradius", def), ry = b.positive(d.params, "yradius", def);
  if (rx != ry) b.note(d.at, "different x and y filter radii are not supported (their mean used)");
  f.radius = 0.5f * (rx + ry);
  f.sigma = 0;
  if (f.type == FilterType::Gaussian) f.sigma = t == "gaussian" ? b.positive(d.params, "sigma", 0.5f) : 0.5f;
  if (t == "mitchell")
    for (const char* k : {"B", "C"})
      if (auto v = d.params.find_float(k); v && std::abs(*v - 1.0 / 3) > 1e-6)
        b.note(d.params.find(k)->at, std::string("Mitchell ") + k + " other than 1/3 is not supported (1/3 used)");
}

void sampler(PbrtBuild& b, const PbrtDirective& d) {
  const std::string& t = d.strings[0];
  SamplerDesc& s = b.out.scene.sampler;
  // pbrt-v4's samplers as the pdrt sampler of the same construction, else the nearest.
  if (t == "zsobol")
    s.type = sampler_name(SamplerKind::ZSobol);
  else if (t == "sobol" || t == "paddedsobol" || t == "halton")
    s.type = sampler_name(SamplerKind::Sobol);
  else if (t == "pmj02bn")
    s.type = sampler_name(SamplerKind::Pmj02bn);
  else if (t == "stratified")
    s.type = sampler_name(SamplerKind::Jitter);
  else if (t == "independent")
    s.type = sampler_name(SamplerKind::Random);
  else
    b.note(d.at, "Sampler \"" + t + "\" is unknown (poisson used)");
  int64_t spp = 16;
  if (t == "stratified") {
    // Each factor on its own first: the product of two large ones would overflow.
    const int64_t xs = d.params.get_int("xsamples", 4), ys = d.params.get_int("ysamples", 4);
    if (xs < 1 || ys < 1 || xs > (int64_t(1) << 24) || ys > (int64_t(1) << 24))
      b.fail(d.at, "\"integer xsamples\" and \"integer ysamples\" must be in [1, 2^24], got " + std::to_string(xs) +
                       " and " + std::to_string(ys));
    spp = xs * ys;
    d.params.find_bool("jitter");
  } else {
    spp = d.params.get_int("pixelsamples", 16);
  }
  if (spp < 1 || spp > (int64_t(1) << 24))
    b.fail(d.at, "the sample count must be in [1, 2^24], got " + std::to_string(spp));
  s.spp = int(spp);
  if (auto seed = d.params.find_int("seed")) s.seed = uint64_t(*seed);
  d.params.find_string("randomization");
}

void integrator(PbrtBuild& b, const PbrtDirective& d) {
  const std::string& t = d.strings[0];
  if (t != "path" && t != "volpath")
    b.fail(d.at, "Integrator \"" + t +
                     "\" is not supported: pdrt is a unidirectional path tracer (use \"path\" or \"volpath\")");
  int64_t depth = d.params.get_int("maxdepth", 5);
  if (depth < 1 || depth > 100000)
    b.fail(d.at, "\"integer maxdepth\" must be in [1, 100000], got " + std::to_string(depth));
  b.out.scene.integrator.max_depth = int(depth);
  if (auto v = d.params.find_string("lightsampler"); v && *v != "bvh")
    b.note(d.params.find("lightsampler")->at,
           "light sampler \"" + *v + "\" is not supported (pdrt's BVH light sampler used)");
  if (auto r = d.params.find_bool("regularize")) b.out.scene.integrator.regularize = *r;
}

// pbrt-v4 CameraBase: the screen window defaults to [-frame, frame] x [-1, 1] when the
// frame aspect ratio (default the film's) is above 1, else [-1, 1] x [-1/frame, 1/frame].
// pdrt's window is on the plane at distance 1 (perspective: pbrt's screen space is that
// scaled by 1/tan(fov/2)) or in scene units (orthographic). Without either parameter the
// default needs no window: pdrt's vfov (build_pbrt_scene) or ortho_height covers it.
void resolve_screen(const PbrtBuild& b, SceneDesc& s) {
  CameraDesc& c = s.camera;
  const bool ortho = c.projection == CameraDesc::Projection::Orthographic;
  const float sx = b.camera.scale[0], sy = b.camera.scale[1];
  if (!b.camera.screen_window && !b.camera.frame_aspect) {
    if (ortho && std::abs(sx - sy) <= 1e-6f * sy)
      c.ortho_height = (s.film.width >= s.film.height ? 2.0f : 2.0f * float(s.film.height) / float(s.film.width)) * sy;
    if (!ortho || std::abs(sx - sy) <= 1e-6f * sy) return;
  }
  const float frame = b.camera.frame_aspect.value_or(float(s.film.width) / float(s.film.height));
  std::array<float, 4> w =
      frame > 1 ? std::array<float, 4>{-frame, frame, -1, 1} : std::array<float, 4>{-1, 1, -1 / frame, 1 / frame};
  if (b.camera.screen_window) w = *b.camera.screen_window;
  const float kx = ortho ? sx : float(std::tan(0.5 * b.camera.fov * kPbrtPi / 180)), ky = ortho ? sy : kx;
  c.screen_window = {w[0] * kx, w[1] * kx, w[2] * ky, w[3] * ky};
  c.has_screen_window = true;
}

}  // namespace

void apply_pbrt_defaults(SceneDesc& s) {
  s.film.width = 1280, s.film.height = 720;  // pbrt-v4's RGBFilm
  s.film.filter = {};
  s.film.filter.type = FilterType::Gaussian, s.film.filter.radius = 1.5f, s.film.filter.sigma = 0.5f;  // GaussianFilter
  s.integrator.max_depth = 5;                                              // VolPathIntegrator, the default integrator
  s.integrator.environment_sampling = EnvironmentSampling::Compensated;    // allowIncompletePDF
  s.sampler.type = sampler_name(SamplerKind::ZSobol), s.sampler.spp = 16;  // ZSobolSampler
}

void translate_pbrt_option(PbrtBuild& b, const PbrtDirective& d) {
  switch (d.kind) {
    case PbrtDirectiveKind::Camera:
      return camera(b, d, b.gs.cur.ctm);
    case PbrtDirectiveKind::Film:
      return film(b, d);
    case PbrtDirectiveKind::PixelFilter:
      return filter(b, d);
    case PbrtDirectiveKind::Sampler:
      return sampler(b, d);
    case PbrtDirectiveKind::Integrator:
      return integrator(b, d);
    default:
      b.fail(d.at, "directive " + d.name + " is not a rendering option");
  }
}

void finish_pbrt_camera(PbrtBuild& b) {
  if (!b.camera.seen) {
    // pbrt-v4's default camera: perspective, fov 90, at the origin looking down +z.
    PbrtDirective d;
    d.name = "Camera";
    d.kind = PbrtDirectiveKind::Camera;
    d.strings = {"perspective"};
    d.at = b.last.value_or(PbrtLocation{});
    camera(b, d, PbrtTransformPair{}, true);
  }
  SceneDesc& s = b.out.scene;
  resolve_screen(b, s);
  // pbrt's fov spans the film's shorter side; pdrt's is vertical.
  FilmDesc& f = s.film;
  const float fov = b.camera.fov;
  const double half = std::tan(0.5 * fov * kPbrtPi / 180);
  s.camera.vfov_deg =
      f.width >= f.height ? fov : float(2 * std::atan(half * double(f.height) / f.width) * 180 / kPbrtPi);
}

}  // namespace pdrt
