#include "renderer/compare/results_json.h"

#include "renderer/compare/blurred_heat_maps.h"
#include "renderer/compare/heat_maps.h"
#include "sampling/core/atomic_file.h"

#include <cmath>

namespace pdrt {

using nlohmann::json;

namespace {

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }
json nan_to_null(double v) { return std::isnan(v) ? json(nullptr) : json(v); }

// How the report's numbers are computed, for whoever reads results.json alone.
json statistics_rules() {
  return {
      {"rmse", "mean over seeds of sqrt(max(0, MSE_k - reference variance))"},
      {"rmse_ci95",
       "half width of the 95% confidence interval of that mean: t(0.975, K-1) sqrt(s^2 / K + (reference.correction_se "
       "/ "
       "(2 rmse))^2), s the spread over seeds"},
      {"variance", "per-pixel variance across seeds (K-1 denominator), averaged over pixels and channels"},
      {"bias2", "mean((seed-average - reference)^2) - variance / K - reference variance"},
      {"mse", "bias2 + variance = mean over seeds of MSE_k - reference variance"},
      {"cpu_seconds", "process CPU time (user + sys, all threads) of the render, without the scene build"},
      {"sampler_share",
       "share of the render passes' CPU time spent computing sample values: SIGPROF ticks (ITIMER_PROF) that "
       "land inside the sampler over all ticks, summed over the seeds; standard_error sqrt(s (1 - s) / ticks)"},
      {"used_samples",
       "per family, each pixel's samples [0, spp) of its bounce-0 stream (seed 0, up to 1024 pixels spread "
       "over the image): relative radius rho of every pixel's prefix (min distance over the densest packing's; "
       "on the torus except the pixel family) and their periodogram averaged over the pixels (power 1 = white "
       "noise, frequency in cycles per unit)"},
      {"blurred_rmse",
       "per sigma (pixels): the RMSE statistics above of the images and the reference blurred by a Gaussian of that "
       "sigma (sampled, cut at 4 sigma, renormalised over the pixels inside the image at its edges), i.e. of the "
       "blurred error; the reference variance is its blurred halves'"},
      {"low_frequency_share",
       "share of the luminance error's power (periodogram, no window, DC i.e. the mean error included) at radial "
       "frequency below 0.25 cycles per pixel, the reference's noise power (from its halves) taken out of both "
       "parts; white error gives pi/16 = 0.196; mean over seeds and t(0.975, K-1) s / sqrt(K)"},
      {"flip",
       "mean over the image of LDR-FLIP (the images clamped to [0, 1], as the PNGs show them) and of HDR-FLIP (the "
       "maximum of LDR-FLIP over ACES-tone-mapped exposures from the reference), Andersson et al. 2020/2021, at "
       "flip.pixels_per_degree; mean over seeds and t(0.975, K-1) s / sqrt(K); the reference's own noise is not "
       "taken out"}};
}

json seed_mean_json(const SeedMean& m) { return {{"mean", finite_or_null(m.mean)}, {"ci95", finite_or_null(m.ci95)}}; }

json screen_json(const UniformRun& r) {
  const ScreenMeasures& m = r.screen;
  json blurred = json::array();
  for (std::size_t s = 0; s < kBlurSigmas.size(); ++s) {
    const SeedStatistics& st = m.blurred[s];
    blurred.push_back({{"sigma", kBlurSigmas[s]},
                       {"rmse", st.rmse_mean},
                       {"rmse_ci95", st.rmse_ci95},
                       {"rmse_low", st.rmse_mean - st.rmse_ci95},
                       {"rmse_high", st.rmse_mean + st.rmse_ci95},
                       {"mse", st.mse_mean},
                       {"bias2", st.bias2},
                       {"variance", st.variance}});
  }
  return {{"blurred_rmse", blurred},
          {"low_frequency_share", seed_mean_json(m.low_share_mean)},
          {"flip",
           {{"ldr", seed_mean_json(m.flip_ldr_mean)},
            {"hdr", seed_mean_json(m.flip_hdr_mean)},
            {"ldr_map", r.flip_ldr_file},
            {"hdr_map", r.flip_hdr_file}}},
          {"spectrum_2d", r.spectrum_file}};
}

// Seed k's screen-space measures, into its per_seed entry.
void add_screen_seed(const ScreenMeasures& m, std::size_t k, json& seed) {
  json blurred = json::array();
  for (const SeedStatistics& st : m.blurred) blurred.push_back(st.rmse[k]);
  seed["blurred_rmse"] = blurred;
  seed["low_frequency_share"] = finite_or_null(m.low_share[k]);
  seed["flip_ldr"] = m.flip_ldr[k];
  seed["flip_hdr"] = m.flip_hdr[k];
}

json reference_json(const CompareReference& ref) {
  const ReferenceSetup& rs = ref.setup;
  const double ref_var = ref.noise.variance;
  return {{"sampler", rs.scene.sampler.type},
          {"spp", rs.scene.sampler.spp},
          {"seed", rs.scene.sampler.seed},
          {"halves",
           {{{"spp", rs.half_spp[0]}, {"seed", rs.half_seed[0]}, {"file", ref.file[0]}},
            {{"spp", rs.half_spp[1]}, {"seed", rs.half_seed[1]}, {"file", ref.file[1]}}}},
          {"variance", ref_var},
          {"variance_rule", "mean over pixels and channels of (a - b)^2 na nb / (na + nb)^2, halves a, b"},
          {"rmse", std::sqrt(ref_var)},
          {"correction_se", ref.noise.correction_se},
          {"cached", ref.cached},
          {"file", ref.file[0]},
          {"seconds", ref.seconds},
          {"image", "images/reference.png"}};
}

json used_json(const StreamAnalysis& a) {
  return {{"family", family_name(a.family)},
          {"bounce", 0},
          {"points", a.spp},
          {"pixels", a.pixels},
          {"periodic", a.periodic},
          {"rho_mean", finite_or_null(a.rho_mean)},
          {"rho_p05", finite_or_null(a.rho_p05)},
          {"rho_min", finite_or_null(a.rho_min)},
          {"resolution", a.resolution},
          {"spectrum", {{"frequency", a.spectrum.frequency}, {"power", a.spectrum.power}}}};
}

json run_json(const UniformRun& r) {
  json used = json::array();
  for (const StreamAnalysis& a : r.used) used.push_back(used_json(a));
  json per_seed = json::array();
  for (std::size_t k = 0; k < r.seeds.size(); ++k) {
    const SeedRun& sr = r.seeds[k];
    per_seed.push_back({{"index", k},
                        {"seed", sr.seed},
                        {"samples", sr.samples},
                        {"seconds", sr.seconds},
                        {"render_seconds", sr.render_seconds},
                        {"cpu_seconds", sr.cpu_seconds},
                        {"mse", r.stats.mse[k]},
                        {"rmse", r.stats.rmse[k]},
                        {"relmse", sr.relmse},
                        {"sampler_share", profile_json(sr.profile)}});
    add_screen_seed(r.screen, k, per_seed.back());
  }
  json j = {{"sampler", r.sampler},
            {"spp", r.spp},
            {"seconds", r.seconds},
            {"render_seconds", r.render_seconds},
            {"cpu_seconds", r.cpu_seconds},
            {"samples", r.samples},
            {"rmse", r.rmse},
            {"rmse_ci95", r.stats.rmse_ci95},
            {"rmse_low", r.rmse - r.stats.rmse_ci95},
            {"rmse_high", r.rmse + r.stats.rmse_ci95},
            {"mse", r.stats.mse_mean},
            {"bias2", r.stats.bias2},
            {"variance", r.stats.variance},
            {"relmse", r.relmse},
            {"sampler_share", profile_json(r.profile)},
            {"sampler_cpu_seconds", finite_or_null(r.profile.share() * r.cpu_seconds)},
            {"used_samples", used},
            {"per_seed", per_seed},
            {"image", r.image_file},
            {"error_map", r.error_file},
            {"blurred_error_map", r.blurred_error_file},
            {"spectrum", {{"frequency", r.spectrum.frequency}, {"power", r.spectrum.power}}}};
  j.update(screen_json(r));
  return j;
}

// The blurred-error maps' scales and the demonstration sheet (null when not drawn), into `j`.
void add_demonstration(const CompareResults& results, json& j) {
  json scale = json::object();
  for (const auto& [n, s] : results.blurred_heat_scale) scale[std::to_string(n)] = s;
  j["blurred_error_maps"] = {
      {"quantity", "seed 0's |Y(blur(image) - blur(reference))| per pixel (linear), Gaussian blur"},
      {"sigma", kBlurredMapSigma},
      {"scale", scale},
      {"scale_rule", "the 99th percentile over every sampler's map at that spp; brighter is clipped"}};
  const DemonstrationSheet& d = results.demonstration;
  if (!d.drawn) {
    j["demonstration"] = nullptr;
    return;
  }
  j["demonstration"] = {
      {"file", d.file},
      {"width", d.width},
      {"height", d.height},
      {"rows", "samplers, in the order of \"samplers\""},
      {"columns", "spp, in the order of \"spp\"; then the reference's crop"},
      {"cell", "seed 0's image crop (left) and its blurred-error heat map crop (right)"},
      {"crop", {{"x", d.window[0]}, {"y", d.window[1]}, {"size", d.window[2]}, {"zoom", d.zoom}}},
      {"crop_rule", d.window_given ? "--demo-crop" : "the detail window (crop_window)"},
      {"sigma", kBlurredMapSigma},
      {"scale", d.scale},
      {"scale_rule", "one heat scale for the whole sheet: the 99th percentile of its cells' blurred errors"},
      {"labelled", d.labelled}};
}

// The screen-space measures' settings and the scales of their pictures, into `j`.
void add_screen_settings(const CompareResults& results, json& j) {
  const FlipExposures& e = results.flip_exposures;
  j["blur_sigmas"] = kBlurSigmas;
  j["low_frequency_cutoff"] = kLowFrequencyCutoff;
  j["flip"] = {{"pixels_per_degree", kFlipPixelsPerDegree},
               {"hdr_exposures", {{"start", e.start}, {"stop", e.stop}, {"count", e.count}}},
               {"maps", "seed 0's per-pixel FLIP on heat_colormap over [0, 1]"}};
  json scale = json::object();
  for (const auto& [n, range] : results.spectrum_scale) scale[std::to_string(n)] = range;
  j["error_spectra_2d"] = {
      {"quantity", "|FFT(luminance error)|^2 / pixels, mean over seeds, DC at the centre, fx right, fy down"},
      {"scale", scale},
      {"scale_rule",
       "log10 power on heat_colormap from scale[0] (at most 6 decades below the largest; the 1st "
       "percentile over the samplers at that spp) to scale[1] (the largest)"}};
}

// The slopes, the samplers' profiled cost and the equal-time view, into `j`.
void add_convergence(const ConvergenceView& v, json& j) {
  json slopes, cost = json::object(), eq_time;
  for (const auto& [name, slope] : v.slopes) slopes[name] = slope;
  for (const auto& [name, total] : v.sampler_cost) cost[name] = profile_json(total);
  j["slopes"] = slopes;
  j["sampler_share"] = cost;
  eq_time["seconds"] = v.seconds;
  eq_time["clock"] = "CPU seconds of the render (user + sys), without the scene build";
  for (const auto& [name, rmse] : v.rmse) {
    eq_time["rmse"][name] = rmse;
    eq_time["rmse_without_sampler"][name] = v.rmse_without_sampler.at(name);
  }
  eq_time["without_sampler"] = "CPU seconds less the sampler's share (sampler_share): what the paths cost";
  j["equal_time"] = eq_time;
}

// The sweep, its step-0 runs and the target, into `j`.
void add_adaptive(const CompareOptions& o, const CompareResults& results, json& j) {
  const AdaptiveDesc& ad = results.adaptive.settings;
  json ja = json::array(), sweep = json::array(), target;
  for (const SamplerSweep& s : results.adaptive.samplers) {
    for (const SweepStep& st : s.steps) {
      const CompareRender& r = st.render;
      sweep.push_back({{"sampler", s.sampler},
                       {"threshold", st.threshold},
                       {"samples", r.samples},
                       {"spp_mean", r.spp_mean},
                       {"rmse", st.rmse},
                       {"rounds", r.adaptive_rounds},
                       {"seconds", r.seconds}});
      if (st.step != 0) continue;
      ja.push_back({{"sampler", s.sampler},
                    {"metric", adaptive_metric_name(ad.metric)},
                    {"variance", adaptive_variance_name(ad.variance)},
                    {"threshold", st.threshold},
                    {"min_spp", ad.min_spp},
                    {"max_spp", ad.max_spp},
                    {"rounds", r.adaptive_rounds},
                    {"spp_mean", r.spp_mean},
                    {"samples", r.samples},
                    {"seconds", r.seconds},
                    {"rmse", st.rmse},
                    {"uniform_rmse_at_equal_samples", nan_to_null(st.uniform_rmse)},
                    {"image", s.image},
                    {"sample_map", s.sample_map},
                    {"sample_map_scale", "log2(samples) / log2(max_spp)"}});
    }
    const UniformRun& at_target = results.runs[s.uniform_run];
    target[s.sampler] = {{"uniform_samples", at_target.samples},
                         {"uniform_rmse", at_target.rmse},
                         {"adaptive_samples", nan_to_null(s.cost.cost)},
                         {"ratio", nan_to_null(s.ratio)},
                         {"upper_bound", s.cost.upper_bound}};
  }
  j["adaptive"] = ja;
  j["adaptive_sweep"] = sweep;
  j["adaptive_target"] = {{"spp", o.adaptive_target_spp}, {"samplers", target}};
  j["adaptive_csv"] = "adaptive.csv";
  j["adaptive_plot"] = "adaptive_vs_spp.png";
}

}  // namespace

json results_json(const ReportContext& ctx, const CompareResults& results) {
  const CompareOptions& o = ctx.o;
  json j;
  j["scene"] = o.scene_label;
  // Biased options the renders used (the reference never uses them): named in the report.
  j["regularize"] = ctx.base.integrator.regularize;
  j["width"] = ctx.width, j["height"] = ctx.height;
  j["seed"] = ctx.base.sampler.seed;
  json seeds = json::array();
  for (int k = 0; k < o.seeds; ++k) seeds.push_back(compare_seed(ctx.base.sampler.seed, k));
  j["seeds"] = seeds;
  j["seed_rule"] = "seed 0 is the scene's sampler.seed; seed k >= 1 is hash_combine(seed, 0x636f6d7061726500 + k)";
  j["statistics"] = statistics_rules();
  j["samplers"] = o.samplers;
  j["spp"] = o.spp;
  j["threads"] = results.threads;
  j["reference"] = reference_json(results.reference);
  j["heat_colormap"] = kHeatStops;
  json heat_scale = json::object();
  for (const auto& [n, scale] : results.heat_scale) heat_scale[std::to_string(n)] = scale;
  j["error_maps"] = {{"quantity", "absolute luminance error per pixel, |Y(image) - Y(reference)| (linear)"},
                     {"scale", heat_scale},
                     {"scale_rule", "the 99th percentile over every sampler's map at that spp; brighter is clipped"}};
  const DetailCrops& c = results.crops;
  j["crop_window"] = {{"x", c.window[0]}, {"y", c.window[1]}, {"size", c.window[2]}, {"zoom", c.zoom}};
  json crops = json::array();
  for (const auto& [n, file] : c.files) crops.push_back({{"spp", n}, {"file", file}});
  j["crops"] = crops;
  json jr = json::array();
  for (const UniformRun& r : results.runs) jr.push_back(run_json(r));
  j["runs"] = jr;
  add_screen_settings(results, j);
  add_demonstration(results, j);
  add_convergence(results.convergence, j);
  if (o.adaptive) add_adaptive(o, results, j);
  return j;
}

std::filesystem::path write_results_json(const ReportContext& ctx, const CompareResults& results) {
  const json j = results_json(ctx, results);
  std::filesystem::path path = ctx.o.out / "results.json";
  write_file_atomically(path, [&](std::ostream& os) { os << j.dump(1) << "\n"; });
  return path;
}

}  // namespace pdrt
