#include "app/compare_request.h"

#include "app/numeric_option.h"
#include "app/python_plots.h"
#include "app/scene_overrides.h"
#include "renderer/compare/compare_job.h"
#include "renderer/compare/demonstration_sheet.h"
#include "renderer/render/renderer.h"
#include "renderer/compare/scene_inputs.h"
#include "renderer/render/sample_budget.h"
#include "renderer/scene/crop_window.h"
#include "renderer/scene/input_files.h"
#include "renderer/scene/render_settings.h"
#include "renderer/scene/scene_limits.h"
#include "renderer/scene/scene_loader.h"
#include "sampling/core/errors.h"
#include "sampling/core/hash.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace pdrt::cli {

namespace {

// The part of `render`'s overrides that compare has: the film's size, the reconstruction, the
// adaptive sweep's metric, variance and decision, and path regularisation, off unless asked (a
// scene's own integrator.regularize is not what compare measures).
SceneOverrides scene_overrides(const CompareRequest& r) {
  SceneOverrides o;
  o.width = r.width, o.height = r.height;
  o.reconstruction = r.reconstruction;
  o.metric = r.adaptive_metric, o.variance = r.adaptive_variance, o.decision = r.adaptive_decision;
  o.regularize = r.regularize;
  return o;
}

// The scene file's bytes and every other file the load read (meshes, included files, textures
// and environment images): the scene's content, which keys the reference cache.
std::string scene_content(const SceneDesc& scene, const InputFileRecord& read) {
  std::string content = read.first_text();
  content += scene_inputs_text(scene, read.files());
  // A resampled environment (a pbrt octahedral map) is also keyed by the pixels made from it.
  if (scene.environment.has_map()) {
    const EnvironmentDesc& e = scene.environment;
    const std::string_view px(reinterpret_cast<const char*>(e.rgb.data()), e.rgb.size() * sizeof(float));
    content +=
        "|environment " + std::to_string(e.width) + "x" + std::to_string(e.height) + " " + std::to_string(fnv1a(px));
  }
  return content;
}

// --demo-crop "x,y,size": three integers (their range against the image is checked once the
// film's size is known).
std::array<int, 3> parse_demo_crop(const std::string& text) {
  std::array<int, 3> v{};
  std::stringstream ss(text);
  std::size_t k = 0;
  for (std::string t; std::getline(ss, t, ',');) {
    if (k == 3) break;
    v[k++] = int(parse_integer_option("--demo-crop", t, IntRange{0, kFilmSizeRange.hi}));
  }
  if (k != 3 || text.back() == ',' || std::count(text.begin(), text.end(), ',') != 2)
    throw UsageError("--demo-crop: give x,y,size (three integers, pixels), got \"" + text + "\"");
  return v;
}

}  // namespace

CompareOptions compare_options(const CompareRequest& r) {
  CompareOptions c;
  auto split = [](const std::string& s) {
    std::vector<std::string> v;
    std::stringstream ss(s);
    for (std::string t; std::getline(ss, t, ',');) v.push_back(t);
    return v;
  };
  c.samplers = split(r.samplers);
  c.spp.clear();
  for (const auto& t : split(r.spp)) c.spp.push_back(int(parse_integer_option("--spp", t, kSppRange)));
  c.adaptive = r.adaptive;
  c.adaptive_threshold = r.adaptive_threshold;
  c.adaptive_target_spp = r.adaptive_target_spp;
  c.reference_spp = r.reference_spp;
  c.seeds = r.seeds;
  c.threads = r.threads;
  c.quiet = r.quiet;
  c.cache_dir = r.cache;
  c.scene_label = r.label.empty() ? r.scene : r.label;
  if (!r.demo_crop.empty()) c.demo_crop = parse_demo_crop(r.demo_crop);
  validate_compare_options(c);
  validate_demo_crop(c, int(kFilmSizeRange.hi), int(kFilmSizeRange.hi));  // the limits on samplers and spp, first
  check_override_names(scene_overrides(r));
  return c;
}

PreparedCompare prepare_compare(const CompareRequest& r, bool check_budget) {
  PreparedCompare p;
  CompareOptions& c = p.options;
  c = compare_options(r);
  SceneDesc& scene = p.scene;
  {
    InputFileRecord read;
    scene = load_scene(r.scene, r.strict);
    c.scene_content = scene_content(scene, read);
  }
  if (check_budget && !r.quiet) {
    if (scene.integrator.regularize && !r.regularize)
      std::fprintf(stderr,
                   "pdrt compare: %s sets integrator.regularize; compare renders without it (unbiased) "
                   "unless --regularize is given\n",
                   r.scene.c_str());
    if (r.regularize)
      std::fprintf(stderr,
                   "pdrt compare: --regularize: the renders are biased (path regularisation), the reference "
                   "is not\n");
  }
  apply_overrides(scene_overrides(r), scene);
  // What compare renders: the scene without adaptive refinement, and with --adaptive the sweep.
  SceneDesc rendered = scene;
  rendered.sampler.adaptive.enabled = false;
  if (c.adaptive) rendered.sampler.adaptive = sweep_adaptive(scene, c);
  check_overridden_settings(rendered);
  {
    const PixelRect crop = crop_pixels(scene.film.crop_window, scene.film.width, scene.film.height);
    validate_demo_crop(c, crop.width(), crop.height());
  }
  // Every sampler at every count, before the reference: the screen-space samplers' pixel order,
  // the image-plane sampler's reconstruction and spp.
  for (const std::string& name : c.samplers)
    for (int spp : c.spp) {
      SamplerDesc d = rendered.sampler;
      d.type = name, d.spp = spp, d.adaptive.enabled = false;
      if (std::string p = sampler_problem(d, rendered.film); !p.empty())
        throw UsageError("--samplers/--spp: sampler " + p);
    }
  if (check_budget) {
    check_film_memory(scene.film.width, scene.film.height,
                      r.width || r.height ? "--width/--height" : scene.film.size_where);
    check_sample_budget(compare_sample_count(c, scene.film.width, scene.film.height), kSecondsPerSample, false,
                        "compare: " + std::to_string(scene.film.width) + "x" + std::to_string(scene.film.height) +
                            " pixels x (reference + " + std::to_string(c.seeds) +
                            " seeds x every sampler at every --spp" + (c.adaptive ? " + the sweep)" : ")"),
                        r.allow_long);
  }
  return p;
}

void write_compare_plots(const std::string& python, const std::filesystem::path& out) {
  ::setenv("MPLBACKEND", "Agg", 1);
  const std::string script = plot_script("renderer/compare/plot_compare.py");
  const std::string log = (out / "plot.log").string();
  if (run_program({python, script, out.string()}, log) != 0)
    throw std::runtime_error("plotting with " + python + " " + script + " failed (see " + log + ")");
  std::filesystem::remove(log);
}

}  // namespace pdrt::cli
