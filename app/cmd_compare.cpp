// `pdrt compare`: progressive jitter vs Poisson (and random, Sobol) noise in real images, measured.
#include "app/commands.h"
#include "app/compare_request.h"
#include "app/numeric_option.h"
#include "app/output_path.h"
#include "app/python_plots.h"
#include "renderer/compare/compare_plan.h"
#include "renderer/compare/demonstration_sheet.h"
#include "renderer/image/image_output.h"
#include "renderer/render/sample_budget.h"
#include "renderer/scene/scene_limits.h"
#include "sampling/core/errors.h"
#include "sampling/core/install_paths.h"

#include <unistd.h>

#include <cstdio>
#include <memory>

namespace pdrt::cli {

// --seeds: one render per seed; more than this many is a typo rather than a study.
inline constexpr IntRange kCompareSeedsRange{1, 1024};

void add_compare_command(CLI::App& app) {
  struct Opts : CompareRequest {
    std::string out, plan;
    bool no_plots = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("compare", "Compare samplers by the error of rendered images against a reference.");
  cmd->add_option("scene", o->scene, "Scene file: pdrt JSON, or pbrt-v4 (*.pbrt)")->required();
  cmd->add_flag("--strict", o->strict, "pbrt scenes: refuse anything pdrt cannot represent instead of listing it");
  auto* out_opt = cmd->add_option("--out,-o", o->out, "Output directory (report, images, plots)");
  auto* plan_opt =
      cmd->add_option("--plan", o->plan,
                      "Write the comparison as a plan of independent jobs into this directory instead of rendering "
                      "(run them with `pdrt run-job`, then `pdrt collect` writes the report there)");
  cmd->add_option("--samplers", o->samplers, "Comma-separated samplers")->default_val(o->samplers);
  cmd->add_option("--spp", o->spp, "Comma-separated, increasing sample counts")->default_val(o->spp);
  cmd->add_flag(
      "--adaptive", o->adaptive,
      "Also sweep adaptive refinement's threshold (x 2^k, k = -4..4, more while needed) against uniform sampling");
  add_real_option(cmd, "--adaptive-threshold", o->adaptive_threshold,
                  "Centre of the sweep (default: the scene's, else the metric's default)");
  cmd->add_option("--adaptive-metric", o->adaptive_metric,
                  name_list(kAdaptiveMetricNames, " | ") + " (default: the scene's)");
  cmd->add_option("--adaptive-variance", o->adaptive_variance,
                  name_list(kAdaptiveVarianceNames, " | ") + " (default: the scene's)");
  cmd->add_option("--adaptive-decision", o->adaptive_decision,
                  name_list(kAdaptiveDecisionNames, " | ") + " (default: the scene's)");
  cmd->add_option(
      "--reconstruction", o->reconstruction,
      name_list(kReconstructionNames, " | ") + ", for every render and the reference (default: the scene's)");
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
  add_integer_option(cmd, "--threads,-t", o->threads, kThreadsRange, "Worker threads (0 = all cores)")
      ->default_str("0");
  cmd->add_option("--demo-crop", o->demo_crop,
                  "x,y,size: the square of the demonstration sheet (images/demonstration.png; drawn for at most " +
                      std::to_string(kDemoMaxSamplers) + " samplers x " + std::to_string(kDemoMaxSpp) +
                      " spp), in image pixels (default: the reference's most detailed square)");
  cmd->add_flag("--regularize", o->regularize,
                "Biased: render with path regularisation (the reference stays unbiased; the report says so)");
  cmd->add_flag("--allow-long-render", o->allow_long, kAllowLongRenderHelp);
  cmd->add_flag("--no-plots", o->no_plots, "Skip the matplotlib plots and index.html");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress on stderr");
  cmd->callback([o, out_opt, plan_opt] {
    const bool planning = plan_opt->count() > 0;
    if (out_opt->count() > 0 && planning)
      throw UsageError("--out and --plan: give one (a plan's report is written into its directory)");
    if (out_opt->count() == 0 && !planning)
      throw UsageError("give --out DIR (the report) or --plan DIR (a plan of jobs)");
    require_output_path(planning ? "--plan" : "-o/--out", planning ? o->plan : o->out);
    compare_options(*o);  // usage errors first
    std::string python;
    if (!o->no_plots && !planning) python = find_plot_python();
    if (planning) {
      // The jobs run elsewhere and later: absolute paths, the label as given.
      CompareRequest r = *o;
      r.label = o->scene;
      r.scene = std::filesystem::absolute(o->scene).string();
      if (!r.cache.empty()) r.cache = std::filesystem::absolute(r.cache).string();
      r.quiet = false;
      const PreparedCompare p = prepare_compare(r, true);
      // Jobs may run on other machines: the absolute path, unless "pdrt" on PATH is this one.
      const std::string self = command_name();
      const ComparePlan plan = write_compare_plan(o->plan, request_json(r), p.options, executable_path());
      const std::size_t left = unfinished_jobs(plan).size();
      if (!o->quiet)
        std::fprintf(stderr,
                     "pdrt compare: wrote the plan %s/plan.json: %zu jobs (%zu to run); run them with\n"
                     "  xargs -P 2 -n 1 %s run-job %s < %s/jobs.txt\n"
                     "then write the report with `%s collect %s` (or see docs/distributed.md)\n",
                     o->plan.c_str(), plan.jobs.size(), left, self.c_str(), o->plan.c_str(), o->plan.c_str(),
                     self.c_str(), o->plan.c_str());
      return;
    }
    PreparedCompare p = prepare_compare(*o, true);
    p.options.out = o->out;
    require_image_io();
    const std::filesystem::path results = run_compare(p.scene, p.options);
    if (!o->no_plots) write_compare_plots(python, p.options.out);
    if (!o->quiet)
      std::fprintf(stderr, "pdrt compare: wrote %s and %s\n", results.c_str(),
                   o->no_plots ? "no plots" : (p.options.out / "index.html").c_str());
  });
}

}  // namespace pdrt::cli
