#include "renderer/compare/uniform_runs.h"

#include "renderer/compare/error_spectrum.h"
#include "renderer/compare/image_metrics.h"
#include "renderer/render/renderer.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace pdrt {

namespace {

// Pixels whose used samples are analysed per (sampler, spp, family): 1024 point sets make
// an averaged periodogram smooth to a few percent.
constexpr int kUsedSamplePixels = 1024;

// Adds seed k's render to `run`: its relative error and times.
void add_seed(const ReportContext& ctx, const Image& ref, int k, const CompareRender& r, UniformRun& run) {
  SeedRun sr;
  sr.seed = compare_seed(ctx.base.sampler.seed, k);
  sr.seconds = r.seconds;
  sr.render_seconds = r.seconds - r.build_seconds;
  sr.cpu_seconds = r.cpu_seconds - r.build_cpu_seconds;
  sr.samples = r.samples;
  sr.relmse = relative_mse(r.image, ref);
  sr.profile = r.profile;
  run.profile += sr.profile;
  if (k == 0) run.samples = r.samples;
  const double w = 1.0 / ctx.o.seeds;
  run.seconds += w * sr.seconds, run.render_seconds += w * sr.render_seconds;
  run.cpu_seconds += w * sr.cpu_seconds, run.relmse += w * sr.relmse, run.spp_mean += w * r.spp_mean;
  run.seeds.push_back(sr);
}

// "poisson     16 spp  rmse 0.09653 +- ...": the run's line of progress.
std::string run_line(const ReportContext& ctx, const UniformRun& run) {
  // One seed has no interval and no split of its error into bias and variance: say so
  // rather than print a zero-width interval and a zero variance.
  char spread[120];
  if (ctx.o.seeds > 1)
    std::snprintf(spread, sizeof spread, "+- %.5f (95%%, %d seeds)  bias^2 %.3g  variance %.3g", run.stats.rmse_ci95,
                  ctx.o.seeds, run.stats.bias2, run.stats.variance);
  else
    std::snprintf(spread, sizeof spread, "(1 seed: intervals, bias and variance need >= 2)");
  char share[48];  // a render too short for a profiler tick has no measured share
  const double sh = run.profile.share();
  if (std::isnan(sh))
    std::snprintf(share, sizeof share, "sampler share not measured: no profiler tick");
  else
    std::snprintf(share, sizeof share, "sampler %.1f%%", 100 * sh);
  char buf[340];
  std::snprintf(buf, sizeof buf, "%-8s %5d spp  rmse %.5f %s  %lld samples  %.3f s CPU (%s)", run.sampler.c_str(),
                run.spp, run.rmse, spread, (long long)run.samples, run.cpu_seconds, share);
  return buf;
}

// "jitter 4 spp  blurred rmse s1 ... s2 ...  low-freq share ...  FLIP ldr ... hdr ...": the
// run's screen-space measures, means over seeds with their 95 % half widths (none for one seed,
// as run_line).
std::string screen_line(const UniformRun& run, int seeds) {
  const ScreenMeasures& m = run.screen;
  auto value = [&](int digits, double mean, double ci) {
    char buf[64];
    if (seeds > 1)
      std::snprintf(buf, sizeof buf, "%.*f +- %.*f", digits, mean, digits, ci);
    else
      std::snprintf(buf, sizeof buf, "%.*f", digits, mean);
    return std::string(buf);
  };
  char head[40];
  std::snprintf(head, sizeof head, "%-8s %5d spp", run.sampler.c_str(), run.spp);
  return std::string(head) + "  blurred rmse s1 " + value(5, m.blurred[0].rmse_mean, m.blurred[0].rmse_ci95) + "  s2 " +
         value(5, m.blurred[1].rmse_mean, m.blurred[1].rmse_ci95) + "  low-freq share " +
         value(3, m.low_share_mean.mean, m.low_share_mean.ci95) + "  FLIP ldr " +
         value(4, m.flip_ldr_mean.mean, m.flip_ldr_mean.ci95) + "  hdr " +
         value(4, m.flip_hdr_mean.mean, m.flip_hdr_mean.ci95);
}

UniformRun render_run(const ReportContext& ctx, const CompareReference& ref, const ScreenReference& screen,
                      const std::string& name, int n, int& threads) {
  UniformRun run;
  run.sampler = name, run.spp = n;
  std::vector<Image> images;
  for (int k = 0; k < ctx.o.seeds; ++k) {
    CompareJob jb;
    jb.kind = CompareJob::Kind::Uniform, jb.sampler = name, jb.spp = n, jb.seed_index = k;
    CompareRender r = ctx.get(jb);
    threads = r.threads;
    add_seed(ctx, ref.image, k, r, run);
    images.push_back(std::move(r.image));
  }
  run.screen = screen_measures(screen, images);
  run.spectrum = radial_spectrum(run.screen.spectrum, ctx.width, ctx.height);
  {
    SamplerDesc d = ctx.base.sampler;
    // The sampler as the runs render it: the screen-space samplers arrange n samples per pixel.
    d.type = name, d.seed = compare_seed(ctx.base.sampler.seed, 0), d.spp = n, d.adaptive.enabled = false;
    const auto sampler = make_scene_sampler(d, ctx.base.film);
    for (int f = 0; f < kFamilyCount; ++f)
      run.used.push_back(analyze_stream(*sampler, Family(f), ctx.width, ctx.height, n, kUsedSamplePixels));
  }
  run.stats = seed_statistics(images, ref.image, ref.noise);
  run.rmse = run.stats.rmse_mean;
  run.image = std::move(images[0]);
  run.image_file = "images/" + name + "-" + std::to_string(n) + ".png";
  run.error_file = "errors/" + name + "-" + std::to_string(n) + ".png";
  ctx.write_png(run.image_file, display_rgb(run.image));
  ctx.say(run_line(ctx, run));
  ctx.say(screen_line(run, ctx.o.seeds));
  return run;
}

}  // namespace

void render_uniform_runs(const ReportContext& ctx, CompareResults& results) {
  const CompareReference& ref = results.reference;
  const ScreenReference screen = screen_reference(ref.image, ref.halves, ref.setup.half_spp);
  results.flip_exposures = screen.hdr.exposures;
  for (const auto& name : ctx.o.samplers)
    for (int n : ctx.o.spp) results.runs.push_back(render_run(ctx, ref, screen, name, n, results.threads));
}

}  // namespace pdrt
