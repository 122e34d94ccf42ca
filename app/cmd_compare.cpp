// `pdrt compare`: progressive jitter vs Poisson (and random, Sobol) noise in real images, measured.
#include "app/commands.h"
#include "app/numeric_option.h"
#include "app/output_path.h"
#include "renderer/render/sample_budget.h"
#include "renderer/scene/scene_limits.h"
#include "renderer/compare/compare.h"
#include "sampling/core/errors.h"
#include "sampling/core/hash.h"
#include "sampling/core/input_file.h"
#include "app/python_plots.h"
#include "renderer/render/image_output.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/scene_loader.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

namespace pdrt::cli {

// --seeds: one render per seed; more than this many is a typo rather than a study.
inline constexpr IntRange kCompareSeedsRange{1, 1024};

void add_compare_command(CLI::App& app) {
  struct Opts {
    std::string scene, out, samplers = "random,jitter,poisson,poisson-02,sobol", spp = "1,4,16,64,256", cache;
    std::optional<int> width, height;
    int reference_spp = 4096, threads = 0, seeds = 4;
    double adaptive_threshold = 0;
    int adaptive_target_spp = 64;
    std::string adaptive_metric, adaptive_variance, adaptive_decision, reconstruction;
    bool adaptive = false, quiet = false, no_plots = false, allow_long = false, strict = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("compare", "Compare samplers by the error of rendered images against a reference.");
  cmd->add_option("scene", o->scene, "Scene file: pdrt JSON, or pbrt-v4 (*.pbrt)")->required();
  cmd->add_flag("--strict", o->strict, "pbrt scenes: refuse anything pdrt cannot represent instead of listing it");
  cmd->add_option("--out,-o", o->out, "Output directory (report, images, plots)")->required();
  cmd->add_option("--samplers", o->samplers, "Comma-separated samplers")->default_val(o->samplers);
  cmd->add_option("--spp", o->spp, "Comma-separated, increasing sample counts")->default_val(o->spp);
  cmd->add_flag("--adaptive", o->adaptive,
                "Also sweep adaptive refinement's threshold (x 2^k, k = -4..4, more while needed) against uniform sampling");
  add_real_option(cmd, "--adaptive-threshold", o->adaptive_threshold,
                  "Centre of the sweep (default: the scene's, else the metric's default)");
  cmd->add_option("--adaptive-metric", o->adaptive_metric,
                  "error-per-sample | relative-error | contrast (default: the scene's)");
  cmd->add_option("--adaptive-variance", o->adaptive_variance, "samples | halves (default: the scene's)");
  cmd->add_option("--adaptive-decision", o->adaptive_decision, "shared | split (default: the scene's)");
  cmd->add_option("--reconstruction", o->reconstruction,
                  "importance | splat | rank, for every render and the reference (default: the scene's)");
  add_integer_option(cmd, "--adaptive-target-spp", o->adaptive_target_spp, kSppRange,
                     "Report the adaptive samples needed to reach the uniform RMSE at this spp (one of --spp)")
      ->default_str("64");
  add_integer_option(cmd, "--reference-spp", o->reference_spp, kSppRange,
                     "Samples per pixel of the reference (two independent halves; their difference is its noise)")
      ->default_str("4096");
  add_integer_option(cmd, "--seeds", o->seeds, kCompareSeedsRange,
                     "Independent seeds per sampler and spp (mean RMSE, 95% interval, bias^2 and variance)")
      ->default_str("4");
  cmd->add_option("--cache-dir", o->cache, "Reference cache directory (default ~/.cache/pdrt/references)");
  add_integer_option(cmd, "--width", o->width, kFilmSizeRange, "Image width (overrides film.width)");
  add_integer_option(cmd, "--height", o->height, kFilmSizeRange, "Image height (overrides film.height)");
  add_integer_option(cmd, "--threads,-t", o->threads, kThreadsRange, "Worker threads (0 = all cores)")->default_str("0");
  cmd->add_flag("--allow-long-render", o->allow_long, kAllowLongRenderHelp);
  cmd->add_flag("--no-plots", o->no_plots, "Skip the matplotlib plots and index.html");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress on stderr");
  cmd->callback([o] {
    CompareOptions c;
    auto split = [](const std::string& s) {
      std::vector<std::string> v;
      std::stringstream ss(s);
      for (std::string t; std::getline(ss, t, ',');) v.push_back(t);
      return v;
    };
    c.samplers = split(o->samplers);
    c.spp.clear();
    for (const auto& t : split(o->spp)) c.spp.push_back(int(parse_integer_option("--spp", t, kSppRange)));
    c.adaptive = o->adaptive;
    c.adaptive_threshold = o->adaptive_threshold;
    c.adaptive_metric = o->adaptive_metric;
    c.adaptive_variance = o->adaptive_variance;
    c.adaptive_decision = o->adaptive_decision;
    c.adaptive_target_spp = o->adaptive_target_spp;
    c.reference_spp = o->reference_spp;
    c.seeds = o->seeds;
    c.threads = o->threads;
    c.quiet = o->quiet;
    c.out = o->out;
    c.cache_dir = o->cache;
    c.scene_label = o->scene;
    require_output_path("-o/--out", o->out);
    validate_compare_options(c);
    Reconstruction recon{};
    if (!o->reconstruction.empty() && !parse_reconstruction(o->reconstruction, &recon))
      throw UsageError("--reconstruction: unknown mode \"" + o->reconstruction + "\" (importance, splat, rank)");
    std::string python;
    if (!o->no_plots) python = find_plot_python();

    SceneDesc scene = load_scene(o->scene, o->strict);
    {
      std::ifstream in = open_for_reading(o->scene);
      std::stringstream ss;
      ss << in.rdbuf();
      c.scene_content = ss.str();
    }
    // An environment image is part of the scene's content too: a regenerated sky must not
    // reuse a reference cached for the old one.
    if (scene.environment.has_map()) {
      const EnvironmentDesc& e = scene.environment;
      const std::string_view px(reinterpret_cast<const char*>(e.rgb.data()), e.rgb.size() * sizeof(float));
      c.scene_content += "|environment " + std::to_string(e.width) + "x" + std::to_string(e.height) + " " +
                         std::to_string(fnv1a(px));
    }
    if (!o->reconstruction.empty()) scene.film.filter.reconstruction = recon;
    const std::string& decision = c.adaptive_decision.empty() ? scene.sampler.adaptive.decision : c.adaptive_decision;
    if (c.adaptive && decision == "split" && scene.film.filter.reconstruction == Reconstruction::Rank)
      throw UsageError("adaptive decision \"split\" needs reconstruction \"importance\" or \"splat\", not \"rank\"");
    if (o->width) scene.film.width = *o->width;
    if (o->height) scene.film.height = *o->height;
    check_film_memory(scene.film.width, scene.film.height,
                      o->width || o->height ? "--width/--height" : scene.film.size_where);
    check_sample_budget(compare_sample_count(c, scene.film.width, scene.film.height),
                        "compare: " + std::to_string(scene.film.width) + "x" + std::to_string(scene.film.height) +
                            " pixels x (reference + " + std::to_string(c.seeds) + " seeds x every sampler at every --spp" + (c.adaptive ? " + the sweep)" : ")"),
                        o->allow_long);
    require_image_io();
    std::filesystem::path results = run_compare(scene, c);
    if (!o->no_plots) {
      ::setenv("MPLBACKEND", "Agg", 1);
      const std::string script = std::string(PDRT_SOURCE_DIR) + "/renderer/compare/plot_compare.py";
      std::string log = (c.out / "plot.log").string();
      if (run_program({python, script, c.out.string()}, log) != 0)
        throw std::runtime_error("plotting with " + python + " " + script + " failed (see " + log + ")");
      std::filesystem::remove(log);
    }
    if (!o->quiet) std::fprintf(stderr, "pdrt compare: wrote %s and %s\n", results.c_str(),
                                o->no_plots ? "no plots" : (c.out / "index.html").c_str());
  });
}

}  // namespace pdrt::cli
