// `pdrt render`: the main job — render a scene file to an image (plus AOVs and stats).
#include "renderer/render/adaptive_metric.h"
#include "sampling/core/atomic_file.h"
#include "app/commands.h"
#include "distributed/mpi_process_group.h"
#include "app/numeric_option.h"
#include "app/output_path.h"
#include "app/partial_summary.h"
#include "app/scene_overrides.h"
#include "renderer/render/sample_budget.h"
#include "renderer/scene/scene_limits.h"
#include "sampling/core/errors.h"
#include "sampling/core/printable.h"
#include "sampling/core/warnings.h"
#include "renderer/image/image_output.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/crop_window.h"
#include "renderer/image/image_module_preload.h"
#include "renderer/scene/scene_loader.h"

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

namespace pdrt::cli {

namespace {

std::atomic<bool> g_cancel{false};
extern "C" void on_interrupt(int) { g_cancel.store(true); }

// Where the samples went (the `samples` AOV): min, max, quantiles and a histogram over
// power-of-two bins [2^k, 2^(k+1)); the first bin, [0, 2), also holds pixels an interrupted
// render left without samples.
nlohmann::json spp_distribution(const std::vector<float>& samples) {
  std::vector<float> s = samples;
  std::sort(s.begin(), s.end());
  nlohmann::json j;
  if (s.empty()) return j;
  auto q = [&](double f) { return s[std::min(s.size() - 1, std::size_t(f * double(s.size())))]; };
  j["min"] = s.front();
  j["p50"] = q(0.5);
  j["p90"] = q(0.9);
  j["p99"] = q(0.99);
  j["max"] = s.back();
  std::vector<int64_t> count;
  for (float v : s) {
    const std::size_t k = v < 2 ? 0 : std::size_t(std::ilogb(v));
    if (k >= count.size()) count.resize(k + 1, 0);
    ++count[k];
  }
  nlohmann::json bins = nlohmann::json::array();
  for (std::size_t k = 0; k < count.size(); ++k)
    if (count[k])
      bins.push_back({{"from", k == 0 ? 0.0 : std::ldexp(1.0, int(k))},
                      {"below", std::ldexp(1.0, int(k) + 1)},
                      {"pixels", count[k]}});
  j["histogram"] = bins;
  return j;
}

// The image's metadata: what rendered it and how.
Metadata image_metadata(const std::string& scene_file, const SceneDesc& scene, const RenderResult& r) {
  const AdaptiveDesc& ad = scene.sampler.adaptive;
  Metadata md = {{"Software", std::string("pdrt ") + PDRT_VERSION},
                 {"pdrt:version", PDRT_VERSION},
                 {"pdrt:scene", scene_file},
                 {"pdrt:sampler", scene.sampler.type},
                 {"pdrt:spp", std::to_string(scene.sampler.spp)},
                 {"pdrt:reconstruction", reconstruction_name(scene.film.filter.reconstruction)},
                 {"pdrt:seed", std::to_string(scene.sampler.seed)},
                 {"pdrt:render_seconds", std::to_string(r.stats.seconds)},
                 {"pdrt:partial", r.stats.partial ? "true" : "false"}};
  // A stopped render: the spp every pixel reached (the progressive passes), and the mean.
  if (r.stats.partial) {
    md.push_back({"pdrt:spp_complete", std::to_string(r.stats.spp_complete)});
    md.push_back({"pdrt:spp_mean", std::to_string(r.stats.spp_mean)});
  }
  // Biased options are named wherever the image goes.
  if (scene.integrator.regularize) md.push_back({"pdrt:regularize", "true"});
  if (ad.enabled)
    md.push_back({"pdrt:adaptive", "min_spp " + std::to_string(ad.min_spp) + ", max_spp " + std::to_string(ad.max_spp) +
                                       ", " + adaptive_metric_name(ad.metric) + " " +
                                       std::to_string(effective_threshold(ad)) + ", decision " +
                                       adaptive_decision_name(ad.decision)});
  return md;
}

// The --stats file.
nlohmann::json stats_json(const std::string& scene_file, const SceneDesc& scene, const RenderResult& r) {
  const AdaptiveDesc& ad = scene.sampler.adaptive;
  nlohmann::json j;
  j["scene"] = scene_file;
  j["sampler"] = scene.sampler.type;
  j["seed"] = scene.sampler.seed;
  j["width"] = scene.film.width;
  j["height"] = scene.film.height;
  if (scene.film.crop_window != std::array<float, 4>{0, 1, 0, 1}) {  // the image is the crop's size
    const PixelRect c = crop_pixels(scene.film.crop_window, scene.film.width, scene.film.height);
    j["crop_pixels"] = {c.x0, c.x1, c.y0, c.y1};
  }
  j["spp"] = scene.sampler.spp;
  j["reconstruction"] = reconstruction_name(scene.film.filter.reconstruction);
  j["regularize"] = scene.integrator.regularize;  // biased when true
  j["seconds"] = r.stats.seconds;
  j["rays"] = r.stats.rays;
  j["mrays_per_second"] = r.stats.seconds > 0 ? r.stats.rays / r.stats.seconds * 1e-6 : 0.0;
  j["samples"] = r.stats.samples;
  j["nonfinite_samples"] = r.stats.nonfinite_samples;
  j["spp_mean"] = r.stats.spp_mean;
  j["spp_complete"] = r.stats.spp_complete;
  j["spp_distribution"] = spp_distribution(r.image.samples);
  if (ad.enabled)
    j["adaptive"] = {{"min_spp", ad.min_spp},
                     {"max_spp", ad.max_spp},
                     {"metric", adaptive_metric_name(ad.metric)},
                     {"threshold", effective_threshold(ad)},
                     {"variance", adaptive_variance_name(ad.variance)},
                     {"decision", adaptive_decision_name(ad.decision)},
                     {"rounds", r.stats.adaptive_rounds}};
  j["cpu_seconds"] = r.stats.cpu_seconds - r.stats.build_cpu_seconds;
  j["sampler_share"] = profile_json(r.stats.sampler_profile);
  j["triangles"] = r.stats.triangles;
  j["threads"] = r.stats.threads;
  j["cpus_allowed"] = r.stats.cpus_allowed;
  // This rank's workers' busy share: thread-seconds in tiles over threads x rendering time.
  const RankStats& me = r.stats.ranks.front();
  const double span = r.stats.threads * (me.seconds - me.exchange_seconds);
  j["threads_busy"] = span > 0 ? me.tile_seconds / span : 0.0;
  j["partial"] = r.stats.partial;
  j["passes_seconds"] = r.stats.passes_seconds;
  const RenderEstimate& e = r.stats.estimate;
  j["estimate"] = {{"seconds", e.seconds},
                   {"ns_per_sample", e.seconds_per_sample * 1e9},
                   {"loop_seconds", e.loop_seconds},
                   {"loops", e.loops},
                   {"calibration_seconds", e.calibration_seconds},
                   {"calibration_cpu_seconds", e.calibration_cpu_seconds},
                   {"calibration_busy_seconds", e.calibration_busy_seconds},
                   {"calibration_pixels", e.calibration_pixels},
                   {"calibration_samples", e.calibration_samples},
                   {"calibration_passes", e.calibration_passes},
                   {"calibration_kept", e.calibration_kept}};
  if (r.stats.ranks.size() > 1) {
    j["ranks"] = nlohmann::json::array();
    for (const RankStats& k : r.stats.ranks)
      j["ranks"].push_back({{"rank", k.rank},
                            {"seconds", k.seconds},
                            {"exchange_seconds", k.exchange_seconds},
                            {"samples", k.samples},
                            {"rays", k.rays},
                            {"tiles", k.tiles},
                            {"bytes_sent", k.bytes_sent},
                            {"tile_seconds", k.tile_seconds}});
  }
  return j;
}

}  // namespace

void add_render_command(CLI::App& app) {
  struct Opts {
    std::string scene, stats;
    std::vector<std::string> outs;
    SceneOverrides set;
    int threads = 0;
    double time_limit = 0;
    bool quiet = false, allow_long = false, strict = false, regularize = false, no_regularize = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("render", "Render a scene file (docs/scene-format.md) to an image.");
  cmd->add_option("scene", o->scene, "Scene file: pdrt JSON, or pbrt-v4 (*.pbrt)")->required();
  cmd->add_flag("--strict", o->strict, "pbrt scenes: refuse anything pdrt cannot represent instead of listing it");
  cmd->add_option("--out,-o", o->outs,
                  "Output image: .exr (linear + AOVs), .png/.jpg (sRGB), .tif (linear); give -o again for more "
                  "formats of the same render")
      ->required()
      ->allow_extra_args(false);
  SceneOverrides& set = o->set;
  add_integer_option(cmd, "--spp", set.spp, kSppRange,
                     "Samples per pixel (overrides sampler.spp; without an adaptive option it also turns the scene's "
                     "sampler.adaptive off)");
  cmd->add_option("--sampler", set.sampler, name_list(kSamplerNames, " | ") + " (overrides sampler.type)");
  add_integer_option(cmd, "--seed", set.seed, kSeedRange, "Sampler seed (overrides sampler.seed)");
  add_integer_option(cmd, "--threads,-t", o->threads, kThreadsRange, "Worker threads (0 = all cores)");
  add_integer_option(cmd, "--width", set.width, kFilmSizeRange, "Image width in pixels (overrides film.width)");
  add_integer_option(cmd, "--height", set.height, kFilmSizeRange, "Image height in pixels (overrides film.height)");
  cmd->add_option("--stats", o->stats, "Write render statistics as JSON to this file");
  cmd->add_option(
      "--reconstruction", set.reconstruction,
      name_list(kReconstructionNames, " | ") + ": how samples become pixels (overrides film.filter.reconstruction)");
  cmd->add_flag("--adaptive", set.adaptive,
                "Adaptive refinement by prefix extension (sampler.adaptive; any --adaptive-* / --min-spp / "
                "--max-spp option turns it on too)");
  add_integer_option(cmd, "--min-spp", set.min_spp, kSppRange,
                     "Adaptive: samples every pixel starts with (sampler.adaptive.min_spp)");
  add_integer_option(cmd, "--max-spp", set.max_spp, kSppRange,
                     "Adaptive: most samples a pixel may take (sampler.adaptive.max_spp)");
  add_real_option(cmd, "--adaptive-threshold", set.threshold,
                  "Adaptive: convergence threshold (default: the metric's)");
  cmd->add_option("--adaptive-metric", set.metric, "Adaptive: " + name_list(kAdaptiveMetricNames, " | "));
  cmd->add_option("--adaptive-variance", set.variance, "Adaptive: " + name_list(kAdaptiveVarianceNames, " | "));
  cmd->add_option("--adaptive-decision", set.decision,
                  "Adaptive: " + name_list(kAdaptiveDecisionNames, " | ") +
                      " (split: odd samples decide, even samples estimate; unbiased)");
  auto* regularize =
      cmd->add_flag("--regularize", o->regularize,
                    "Biased: path regularisation, roughening near-specular lobes after the first non-specular bounce "
                    "(integrator.regularize)");
  cmd->add_flag("--no-regularize", o->no_regularize, "Unbiased: no path regularisation, whatever the scene sets")
      ->excludes(regularize);
  cmd->add_flag("--allow-long-render", o->allow_long, kAllowLongRenderHelp);
  add_real_option(cmd, "--time-limit", o->time_limit,
                  "Stop after this many seconds (the scene build included) and write the image at the spp every "
                  "pixel reached, marked partial; no sample budget then",
                  true);
  cmd->add_flag("--quiet,-q", o->quiet, "No progress or summary on stderr");
  cmd->callback([o] {
    // Under mpirun every rank loads the same scene and renders the same image: rank 0 speaks
    // for all (errors: app/main.cpp), and the render hands the others' warnings to it.
    if (launcher_rank() != 0) hold_warnings();
    // Validate every argument before loading or rendering anything (numbers are checked
    // while parsing: app/numeric_option.h).
    for (const auto& out : o->outs) require_output_path("-o/--out", out);
    check_override_names(o->set);
    for (std::size_t i = 0; i < o->outs.size(); ++i) {
      check_image_extension(o->outs[i]);
      for (std::size_t k = 0; k < i; ++k)
        if (std::filesystem::path(o->outs[k]).lexically_normal() ==
            std::filesystem::path(o->outs[i]).lexically_normal())
          throw UsageError("--out " + o->outs[i] + " is given twice");
    }

    // --threads bounds the whole command, not only the passes: the scene's set-up and the
    // image's conversion and writing run in parallel too.
    std::optional<tbb::global_control> limit;
    if (o->threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(o->threads));
    // Rank 0 writes the image: its module loads while the scene does.
    std::optional<ImageModulePreload> preload;
    if (launcher_rank() == 0) preload.emplace();
    SceneDesc scene = load_scene(o->scene, o->strict);
    if (o->regularize) o->set.regularize = true;
    if (o->no_regularize) o->set.regularize = false;
    if (spp_turns_adaptive_off(o->set, scene))
      warn("pdrt render: --spp " + std::to_string(*o->set.spp) +
           " renders that many samples in every pixel: the scene's adaptive refinement (sampler.adaptive) is off; "
           "--adaptive keeps it");
    apply_overrides(o->set, scene);
    check_overridden_settings(scene);
    const AdaptiveDesc& ad = scene.sampler.adaptive;
    const bool split = ad.enabled && ad.decision == AdaptiveDecision::Split;
    check_film_memory(scene.film.width, scene.film.height,
                      o->set.width || o->set.height ? "--width/--height" : scene.film.size_where, split ? 2 : 1);
    for (const auto& out : o->outs) check_writable(out);
    if (!o->stats.empty()) check_writable(o->stats);

    // MPI starts here under mpirun (before the handlers below, so that they are pdrt's).
    const ProcessGroup& group = process_group();
    // Ctrl-C from here on gives the partial image, even while the image module loads.
    auto previous = std::signal(SIGINT, on_interrupt);
    // Under mpirun, Ctrl-C reaches the ranks as SIGTERM (Open MPI's mpirun ends the job with
    // it, and a SIGKILL a second later), and mpirun passes SIGUSR1 on without ending the job:
    // both interrupt like SIGINT (docs/distributed.md).
    const bool mpi = launched_by_mpi();
    auto previous_term = mpi ? std::signal(SIGTERM, on_interrupt) : SIG_DFL;
    auto previous_usr1 = mpi ? std::signal(SIGUSR1, on_interrupt) : SIG_DFL;
    // Under mpirun the ranks share the render (docs/distributed.md); rank 0 reports and writes.
    const bool lead = launcher_rank() == 0, quiet = o->quiet || !lead;
    // The last check: a missing module is refused before anything is said or rendered. Only
    // the rank that writes needs it (OpenImageIO's libraries cost a process 0.2 s of CPU and
    // 40 MB; a scene's textures load it where they are read), so only rank 0 meets a broken
    // one, and ends the others rather than let them wait for it.
    preload.reset();
    if (lead) try {
        require_image_io();
      } catch (const std::exception& e) {
        if (group.size() == 1) throw;
        std::fprintf(stderr, "pdrt: %s\n", printable(e.what()).c_str());
        abort_process_group(1);
      }
    auto sampler = make_scene_sampler(scene.sampler, scene.film);
    RenderOptions ro;
    ro.threads = o->threads;
    ro.quiet = quiet;
    ro.cancel = &g_cancel;
    ro.group = &group;
    ro.time_limit = o->time_limit;
    // The cost, timed on this scene after its build (render_estimate.h), before any pass.
    ro.on_estimate = [&](const RenderEstimate& e) {
      if (o->time_limit <= 0)
        check_sample_budget(e.samples, e.seconds_per_sample, true, describe_sample_count(scene), o->allow_long);
      if (!quiet)
        std::fprintf(stderr, "pdrt render: %s = %s\n", describe_sample_count(scene).c_str(),
                     format_sample_cost(e.samples, e.seconds_per_sample, true, e.loops * e.loop_seconds).c_str());
    };
    RenderResult r = render(scene, *sampler, ro);
    std::signal(SIGINT, previous);
    if (mpi) std::signal(SIGTERM, previous_term), std::signal(SIGUSR1, previous_usr1);
    if (!lead) {
      if (r.stats.partial && g_cancel.load()) throw InterruptedError("interrupted");
      return;
    }

    // One render, every requested format; each file is written all-or-nothing.
    const Metadata md = image_metadata(o->scene, scene, r);
    for (const auto& out : o->outs) write_image(out, r.image, md);
    if (!o->stats.empty()) {
      const nlohmann::json j = stats_json(o->scene, scene, r);
      write_file_atomically(o->stats, [&](std::ostream& os) { os << j.dump(2) << "\n"; });
    }
    std::string names;
    for (const auto& out : o->outs) names += (names.empty() ? "" : ", ") + out;
    // A stopped render's mean spp says nothing of which pixels got samples: the spp every
    // pixel reached says it, and the line after this one counts them.
    char spp[96];
    if (r.stats.partial)
      std::snprintf(spp, sizeof spp, "partial: every pixel at %lld spp or more, mean %.1f spp",
                    (long long)r.stats.spp_complete, r.stats.spp_mean);
    else
      std::snprintf(spp, sizeof spp, "%.1f spp", r.stats.spp_mean);
    if (!o->quiet)
      std::fprintf(stderr, "pdrt render: %s %dx%d, %s, %s, %.2f s, %.2f Mrays/s%s\n", names.c_str(), scene.film.width,
                   scene.film.height, scene.sampler.type.c_str(), spp, r.stats.seconds,
                   r.stats.seconds > 0 ? r.stats.rays / r.stats.seconds * 1e-6 : 0.0,
                   scene.integrator.regularize ? ", regularized (biased)" : "");
    const std::string coverage =
        r.stats.partial ? describe_partial_coverage(r.image.samples, ad.enabled ? 0 : scene.sampler.spp) : "";
    if (r.stats.partial && g_cancel.load())
      throw InterruptedError("interrupted; wrote the partial image " + names + ": " + coverage);
    if (r.stats.partial && !o->quiet)  // the time limit: what was asked for, exit 0
      std::fprintf(stderr, "pdrt render: stopped at the time limit of %g s; wrote %s: %s\n", o->time_limit,
                   names.c_str(), coverage.c_str());
  });
}

}  // namespace pdrt::cli
