// `pdrt compare`: progressive jitter vs Poisson (and random, Sobol) noise in real images, measured.
#include "app/commands.h"
#include "renderer/compare/compare.h"
#include "sampling/core/errors.h"
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

void add_compare_command(CLI::App& app) {
  struct Opts {
    std::string scene, out, samplers = "random,jitter,poisson,sobol", spp = "1,4,16,64,256", cache;
    std::optional<int> width, height;
    int reference_spp = 4096, threads = 0;
    double adaptive_threshold = 0;
    int adaptive_target_spp = 64;
    std::string adaptive_metric, adaptive_variance;
    bool adaptive = false, quiet = false, no_plots = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("compare", "Compare samplers by the error of rendered images against a reference.");
  cmd->add_option("scene", o->scene, "Scene JSON file")->required();
  cmd->add_option("--out,-o", o->out, "Output directory (report, images, plots)")->required();
  cmd->add_option("--samplers", o->samplers, "Comma-separated samplers")->default_val(o->samplers);
  cmd->add_option("--spp", o->spp, "Comma-separated, increasing sample counts")->default_val(o->spp);
  cmd->add_flag("--adaptive", o->adaptive,
                "Also sweep adaptive refinement's threshold (x 2^k, k = -4..4, more while needed) against uniform sampling");
  cmd->add_option("--adaptive-threshold", o->adaptive_threshold,
                  "Centre of the sweep (default: the scene's, else the metric's default)");
  cmd->add_option("--adaptive-metric", o->adaptive_metric,
                  "error-per-sample | relative-error | contrast (default: the scene's)");
  cmd->add_option("--adaptive-variance", o->adaptive_variance, "samples | halves (default: the scene's)");
  cmd->add_option("--adaptive-target-spp", o->adaptive_target_spp,
                  "Report the adaptive samples needed to reach the uniform RMSE at this spp (one of --spp)")
      ->default_val(64);
  cmd->add_option("--reference-spp", o->reference_spp, "Samples per pixel of the reference")->default_val(4096);
  cmd->add_option("--cache-dir", o->cache, "Reference cache directory (default ~/.cache/pdrt/references)");
  cmd->add_option("--width", o->width, "Image width (overrides film.width)");
  cmd->add_option("--height", o->height, "Image height (overrides film.height)");
  cmd->add_option("--threads,-t", o->threads, "Worker threads (0 = all cores)")->default_val(0);
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
    for (const auto& t : split(o->spp)) {
      char* end = nullptr;
      long v = std::strtol(t.c_str(), &end, 10);
      if (t.empty() || *end || v < 1 || v > (1 << 24)) throw UsageError("--spp: \"" + t + "\" is not a sample count");
      c.spp.push_back(int(v));
    }
    c.adaptive = o->adaptive;
    c.adaptive_threshold = o->adaptive_threshold;
    c.adaptive_metric = o->adaptive_metric;
    c.adaptive_variance = o->adaptive_variance;
    c.adaptive_target_spp = o->adaptive_target_spp;
    c.reference_spp = o->reference_spp;
    c.threads = o->threads;
    c.quiet = o->quiet;
    c.out = o->out;
    c.cache_dir = o->cache;
    c.scene_label = o->scene;
    if (o->threads < 0) throw UsageError("--threads must be >= 0, got " + std::to_string(o->threads));
    if (o->width && (*o->width < 1 || *o->width > 65536)) throw UsageError("--width must be in [1, 65536]");
    if (o->height && (*o->height < 1 || *o->height > 65536)) throw UsageError("--height must be in [1, 65536]");
    validate_compare_options(c);
    std::string python;
    if (!o->no_plots) python = find_plot_python();

    SceneDesc scene = load_scene(o->scene);
    {
      std::ifstream in(o->scene, std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      c.scene_content = ss.str();
    }
    if (o->width) scene.film.width = *o->width;
    if (o->height) scene.film.height = *o->height;
    check_film_memory(scene.film.width, scene.film.height);
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
