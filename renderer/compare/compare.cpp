#include "renderer/compare/compare.h"

#include "renderer/render/adaptive_metric.h"
#include "sampling/core/atomic_file.h"
#include "renderer/compare/compare_job.h"
#include "renderer/compare/convergence.h"
#include "sampling/core/errors.h"
#include "sampling/core/output_directory.h"
#include "renderer/compare/image_metrics.h"
#include "renderer/compare/seed_statistics.h"
#include "sampling/analysis/stream_analysis.h"
#include "renderer/image/image_output.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/crop_window.h"
#include "sampling/samplers/sampler.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

namespace pdrt {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Pixels whose used samples are analysed per (sampler, spp, family): 1024 point sets make
// an averaged periodogram smooth to a few percent.
constexpr int kUsedSamplePixels = 1024;

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

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

// A perceptually ordered dark-to-bright colour ramp for heat maps, in display RGB at t = 0,
// 1/4, ..., 1 (results.json carries it so the report's colour bars match the PNGs).
constexpr float kHeatStops[5][3] = {
    {0, 0, 0.02f}, {0.33f, 0.06f, 0.43f}, {0.73f, 0.21f, 0.33f}, {0.98f, 0.55f, 0.04f}, {0.99f, 1.0f, 0.64f}};

Vec3 heat(float t) {
  t = std::clamp(t, 0.0f, 1.0f) * 4;
  int i = std::min(int(t), 3);
  const auto& a = kHeatStops[i];
  const auto& b = kHeatStops[i + 1];
  return lerp(t - i, Vec3(a[0], a[1], a[2]), Vec3(b[0], b[1], b[2]));
}

std::vector<float> display_rgb(const Image& im) {
  std::vector<float> out(im.rgb.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = linear_to_srgb(im.rgb[i]);
  return out;
}

// One seed's render of a (sampler, spp).
struct SeedRun {
  uint64_t seed = 0;
  double seconds = 0, render_seconds = 0, cpu_seconds = 0, relmse = 0;
  int64_t samples = 0;
  SamplerProfile profile;  // the sampler's share of the passes' CPU ticks
};

// A (sampler, spp) over every seed; `rmse` is the mean over seeds of the reference-corrected RMSE.
struct Run {
  std::string sampler;
  int spp = 0;
  double seconds = 0, render_seconds = 0, cpu_seconds = 0, rmse = 0, relmse = 0, spp_mean = 0;  // means over seeds
  int64_t samples = 0;  // traced by one render (every seed traces the same count)
  SeedStatistics stats;
  std::vector<SeedRun> seeds;
  RadialSpectrum spectrum;  // of the error image, averaged over the seeds
  SamplerProfile profile;   // summed over the seeds
  std::vector<StreamAnalysis> used;  // seed 0's samples, per family
  Image image;              // seed 0's
  std::string image_file, error_file;
};

// The crop window (side c) where the reference has the most detail (sum of gradient norms).
std::array<int, 3> detail_window(const Image& ref) {
  const int W = ref.width, H = ref.height, c = std::max(8, std::min(W, H) / 4);
  std::vector<double> g(std::size_t(W) * H, 0.0);
  auto L = [&](int x, int y) {
    std::size_t i = 3 * (std::size_t(y) * W + x);
    return double(luminance(Vec3(ref.rgb[i], ref.rgb[i + 1], ref.rgb[i + 2])));
  };
  for (int y = 0; y + 1 < H; ++y)
    for (int x = 0; x + 1 < W; ++x) {
      double a = L(x, y);
      g[std::size_t(y) * W + x] = std::abs(L(x + 1, y) - a) + std::abs(L(x, y + 1) - a);
    }
  std::array<int, 3> best{0, 0, c};
  double best_v = -1;
  const int step = std::max(1, c / 4);
  for (int y0 = 0; y0 + c <= H; y0 += step)
    for (int x0 = 0; x0 + c <= W; x0 += step) {
      double v = 0;
      for (int y = y0; y < y0 + c; ++y)
        for (int x = x0; x < x0 + c; ++x) v += g[std::size_t(y) * W + x];
      if (v > best_v) best_v = v, best = {x0, y0, c};
    }
  return best;
}

}  // namespace

void validate_compare_options(const CompareOptions& o) {
  if (o.samplers.empty()) throw UsageError("--samplers: give at least one sampler");
  std::set<std::string> seen;
  for (const auto& s : o.samplers) {
    const auto& names = all_sampler_names();
    if (std::find(names.begin(), names.end(), s) == names.end())
      throw UsageError("--samplers: unknown sampler \"" + s + "\" (" + sampler_name_list() + ")");
    if (!seen.insert(s).second) throw UsageError("--samplers: \"" + s + "\" given twice");
  }
  if (o.spp.empty()) throw UsageError("--spp: give at least one sample count");
  for (std::size_t i = 0; i < o.spp.size(); ++i) {
    if (o.spp[i] < 1) throw UsageError("--spp: sample counts must be >= 1, got " + std::to_string(o.spp[i]));
    if (i && o.spp[i] <= o.spp[i - 1]) throw UsageError("--spp: sample counts must increase");
  }
  if (!o.adaptive_metric.empty()) require_adaptive_choice("--adaptive-metric", o.adaptive_metric, kAdaptiveMetrics);
  if (!o.adaptive_variance.empty())
    require_adaptive_choice("--adaptive-variance", o.adaptive_variance, kAdaptiveVariances);
  if (!o.adaptive_decision.empty())
    require_adaptive_choice("--adaptive-decision", o.adaptive_decision, kAdaptiveDecisions);
  if (o.adaptive_threshold < 0) throw UsageError("--adaptive-threshold must be > 0");
  if (o.adaptive && std::find(o.spp.begin(), o.spp.end(), o.adaptive_target_spp) == o.spp.end())
    throw UsageError("--adaptive-target-spp " + std::to_string(o.adaptive_target_spp) +
                     " must be one of the --spp sample counts");
  if (o.seeds < 1) throw UsageError("--seeds must be >= 1, got " + std::to_string(o.seeds));
  if (o.reference_spp < 1) throw UsageError("--reference-spp must be >= 1, got " + std::to_string(o.reference_spp));
  if (o.reference_spp < 4 * o.spp.back())
    throw UsageError("--reference-spp must be at least 4x the largest --spp (" + std::to_string(o.spp.back()) +
                     "), i.e. >= " + std::to_string(4 * o.spp.back()) + ", got " + std::to_string(o.reference_spp));
}

double compare_sample_count(const CompareOptions& o, int width, int height) {
  double per_pixel = o.reference_spp;
  for (int spp : o.spp) per_pixel += double(o.seeds) * double(o.samplers.size()) * spp;
  if (o.adaptive && !o.spp.empty())
    per_pixel += double(kSweepLastStep - kSweepFirstStep + 1) * double(o.samplers.size()) * o.spp.back();
  return per_pixel * width * height;
}

fs::path write_compare_report(const SceneDesc& base, const CompareOptions& o, const CompareJobSource& source) {
  validate_compare_options(o);
  create_output_directory(o.out);
  std::error_code ec;
  for (const char* sub : {"images", "errors"}) {
    fs::create_directories(o.out / sub, ec);
    if (ec) throw InputError((o.out / sub).string() + ": cannot create directory (" + ec.message() + ")");
  }
  check_writable(o.out / "results.json");
  // Every image is the crop window's (the whole film without one).
  const PixelRect crop = crop_pixels(base.film.crop_window, base.film.width, base.film.height);
  if (crop.empty()) throw InputError(base.film.size_where + ": film.crop_window covers no pixel of the film");
  const int W = crop.width(), H = crop.height();
  auto say = [&](const std::string& s) {
    if (!o.quiet) std::fprintf(stderr, "pdrt compare: %s\n", s.c_str());
  };

  // A job's render; a plan's job file of another size is refused rather than misread.
  auto get = [&](const CompareJob& jb) {
    CompareRender r = source(jb);
    if (r.image.width != W || r.image.height != H)
      throw InputError(describe(jb) + ": its image is " + std::to_string(r.image.width) + "x" +
                       std::to_string(r.image.height) + ", the film " + std::to_string(W) + "x" + std::to_string(H));
    return r;
  };

  // The reference (compare_job.h): two halves whose difference measures its noise.
  const ReferenceSetup rs = reference_setup(base, o);
  const auto& half_spp = rs.half_spp;
  const auto& half_seed = rs.half_seed;
  Image halves[2];
  std::string ref_file[2];
  bool cached = true;
  double ref_seconds = 0;
  for (int h = 0; h < 2; ++h) {
    CompareJob jb;
    jb.kind = CompareJob::Kind::Reference, jb.half = h;
    CompareRender r = get(jb);
    halves[h] = std::move(r.image);
    ref_file[h] = r.file;
    cached = cached && r.cached;
    if (!r.cached) ref_seconds += r.seconds;
  }
  Image ref = halves[0];
  for (std::size_t i = 0; i < ref.rgb.size(); ++i)
    ref.rgb[i] = float((double(halves[0].rgb[i]) * half_spp[0] + double(halves[1].rgb[i]) * half_spp[1]) /
                       double(o.reference_spp));
  const ReferenceNoise ref_noise = reference_noise(halves[0], half_spp[0], halves[1], half_spp[1]);
  const double ref_var = ref_noise.variance;
  {
    char buf[160];
    std::snprintf(buf, sizeof buf, "reference variance %.4g per pixel channel (RMSE %.5f), subtracted from every MSE",
                  ref_var, std::sqrt(ref_var));
    say(buf);
  }
  // RMSE against the reference with its variance taken out (E[(x - r)^2] = E[(x - I)^2] + Var r).
  auto corrected_rmse = [&](const Image& im) {
    const double e = rmse(im, ref);
    return std::sqrt(std::max(0.0, e * e - ref_var));
  };
  write_display_png(o.out / "images" / "reference.png", W, H, display_rgb(ref));

  std::vector<Run> runs;
  int threads_used = 0;
  for (const auto& name : o.samplers)
    for (int n : o.spp) {
      Run run;
      run.sampler = name, run.spp = n;
      std::vector<Image> images;
      for (int k = 0; k < o.seeds; ++k) {
        CompareJob jb;
        jb.kind = CompareJob::Kind::Uniform, jb.sampler = name, jb.spp = n, jb.seed_index = k;
        CompareRender r = get(jb);
        threads_used = r.threads;
        SeedRun sr;
        sr.seed = compare_seed(base.sampler.seed, k);
        sr.seconds = r.seconds;
        sr.render_seconds = r.seconds - r.build_seconds;
        sr.cpu_seconds = r.cpu_seconds - r.build_cpu_seconds;
        sr.samples = r.samples;
        sr.relmse = relative_mse(r.image, ref);
        sr.profile = r.profile;
        run.profile += sr.profile;
        RadialSpectrum sp = error_spectrum(r.image, ref);
        if (k == 0) run.spectrum = sp, run.samples = r.samples;
        else
          for (std::size_t b = 0; b < sp.power.size(); ++b) run.spectrum.power[b] += sp.power[b];
        const double w = 1.0 / o.seeds;
        run.seconds += w * sr.seconds, run.render_seconds += w * sr.render_seconds;
        run.cpu_seconds += w * sr.cpu_seconds, run.relmse += w * sr.relmse, run.spp_mean += w * r.spp_mean;
        run.seeds.push_back(sr);
        images.push_back(std::move(r.image));
      }
      for (double& p : run.spectrum.power) p /= o.seeds;
      {
        SamplerDesc d = base.sampler;
        d.type = name, d.seed = compare_seed(base.sampler.seed, 0);
        const auto sampler = make_scene_sampler(d);
        for (int f = 0; f < kFamilyCount; ++f)
          run.used.push_back(analyze_stream(*sampler, Family(f), W, H, n, kUsedSamplePixels));
      }
      run.stats = seed_statistics(images, ref, ref_noise);
      run.rmse = run.stats.rmse_mean;
      run.image = std::move(images[0]);
      run.image_file = "images/" + name + "-" + std::to_string(n) + ".png";
      run.error_file = "errors/" + name + "-" + std::to_string(n) + ".png";
      write_display_png(o.out / run.image_file, W, H, display_rgb(run.image));
      // One seed has no interval and no split of its error into bias and variance: say so
      // rather than print a zero-width interval and a zero variance.
      char spread[120];
      if (o.seeds > 1)
        std::snprintf(spread, sizeof spread, "+- %.5f (95%%, %d seeds)  bias^2 %.3g  variance %.3g", run.stats.rmse_ci95,
                      o.seeds, run.stats.bias2, run.stats.variance);
      else
        std::snprintf(spread, sizeof spread, "(1 seed: intervals, bias and variance need >= 2)");
      char share[48];  // a render too short for a profiler tick has no measured share
      const double sh = run.profile.share();
      if (std::isnan(sh)) std::snprintf(share, sizeof share, "sampler share not measured: no profiler tick");
      else std::snprintf(share, sizeof share, "sampler %.1f%%", 100 * sh);
      char buf[340];
      std::snprintf(buf, sizeof buf, "%-8s %5d spp  rmse %.5f %s  %lld samples  %.3f s CPU (%s)", name.c_str(), n, run.rmse,
                    spread, (long long)run.samples, run.cpu_seconds, share);
      say(buf);
      runs.push_back(std::move(run));
    }

  // Heat maps share one scale per sample count (the 99th percentile over the samplers), so
  // they compare across samplers.
  json heat_scale = json::object();
  for (int n : o.spp) {
    std::vector<float> all;
    std::map<std::string, std::vector<float>> maps;
    for (const Run& r : runs)
      if (r.spp == n) {
        maps[r.sampler] = error_map(r.image, ref);
        all.insert(all.end(), maps[r.sampler].begin(), maps[r.sampler].end());
      }
    std::sort(all.begin(), all.end());
    float scale = std::max(all[std::size_t(0.99 * (all.size() - 1))], 1e-6f);
    heat_scale[std::to_string(n)] = scale;
    for (const Run& r : runs)
      if (r.spp == n) {
        const auto& m = maps[r.sampler];
        std::vector<float> rgb(3 * m.size());
        for (std::size_t i = 0; i < m.size(); ++i) {
          Vec3 c = heat(m[i] / scale);
          rgb[3 * i] = c.x, rgb[3 * i + 1] = c.y, rgb[3 * i + 2] = c.z;
        }
        write_display_png(o.out / r.error_file, W, H, rgb);
      }
  }

  // Side-by-side crops of the most detailed region, at every sample count.
  auto win = detail_window(ref);
  const int c = win[2], zoom = std::max(1, 128 / c), gap = 4;
  const int cols = int(o.samplers.size()) + 1, cw = c * zoom, CW = cols * cw + (cols - 1) * gap;
  json crops = json::array();
  for (int n : o.spp) {
    std::vector<float> rgb(std::size_t(3) * CW * cw, 1.0f);
    auto paste = [&](const Image& im, int col) {
      for (int y = 0; y < cw; ++y)
        for (int x = 0; x < cw; ++x) {
          std::size_t si = 3 * (std::size_t(win[1] + y / zoom) * W + win[0] + x / zoom);
          std::size_t di = 3 * (std::size_t(y) * CW + col * (cw + gap) + x);
          for (int k = 0; k < 3; ++k) rgb[di + k] = linear_to_srgb(im.rgb[si + k]);
        }
    };
    int col = 0;
    for (const auto& name : o.samplers)
      for (const Run& r : runs)
        if (r.sampler == name && r.spp == n) paste(r.image, col++);
    paste(ref, col);
    std::string file = "images/crops-" + std::to_string(n) + ".png";
    write_display_png(o.out / file, CW, cw, rgb);
    crops.push_back({{"spp", n}, {"file", file}});
  }

  json j;
  j["scene"] = o.scene_label;
  // Biased options the renders used (the reference never uses them): named in the report.
  j["regularize"] = base.integrator.regularize;
  j["width"] = W, j["height"] = H;
  j["seed"] = base.sampler.seed;
  {
    json seeds = json::array();
    for (int k = 0; k < o.seeds; ++k) seeds.push_back(compare_seed(base.sampler.seed, k));
    j["seeds"] = seeds;
  }
  j["seed_rule"] = "seed 0 is the scene's sampler.seed; seed k >= 1 is hash_combine(seed, 0x636f6d7061726500 + k)";
  j["statistics"] = {
      {"rmse", "mean over seeds of sqrt(max(0, MSE_k - reference variance))"},
      {"rmse_ci95",
       "half width of the 95% confidence interval of that mean: t(0.975, K-1) sqrt(s^2 / K + (reference.correction_se / "
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
       "noise, frequency in cycles per unit)"}};
  j["samplers"] = o.samplers;
  j["spp"] = o.spp;
  j["threads"] = threads_used;
  j["reference"] = {{"sampler", rs.scene.sampler.type},
                    {"spp", rs.scene.sampler.spp},
                    {"seed", rs.scene.sampler.seed},
                    {"halves", {{{"spp", half_spp[0]}, {"seed", half_seed[0]}, {"file", ref_file[0]}},
                                {{"spp", half_spp[1]}, {"seed", half_seed[1]}, {"file", ref_file[1]}}}},
                    {"variance", ref_var},
                    {"variance_rule", "mean over pixels and channels of (a - b)^2 na nb / (na + nb)^2, halves a, b"},
                    {"rmse", std::sqrt(ref_var)},
                    {"correction_se", ref_noise.correction_se},
                    {"cached", cached},
                    {"file", ref_file[0]},
                    {"seconds", ref_seconds},
                    {"image", "images/reference.png"}};
  j["heat_colormap"] = kHeatStops;
  j["error_maps"] = {{"quantity", "absolute luminance error per pixel, |Y(image) - Y(reference)| (linear)"},
                     {"scale", heat_scale},
                     {"scale_rule", "the 99th percentile over every sampler's map at that spp; brighter is clipped"}};
  j["crop_window"] = {{"x", win[0]}, {"y", win[1]}, {"size", win[2]}, {"zoom", zoom}};
  j["crops"] = crops;
  json jr = json::array();
  for (const Run& r : runs) {
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
    }
    jr.push_back({{"sampler", r.sampler},
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
                  {"spectrum", {{"frequency", r.spectrum.frequency}, {"power", r.spectrum.power}}}});
  }
  j["runs"] = jr;

  // Convergence slopes (RMSE ~ spp^slope) and the equal-time view.
  json slopes, eq_time;
  double t_lo = 0, t_hi = 1e300;
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> by_time, by_time_net;
  json cost = json::object();
  for (const auto& name : o.samplers) {
    std::vector<double> x, y, t, t_net;
    SamplerProfile total;
    for (const Run& r : runs)
      if (r.sampler == name) {
        x.push_back(r.spp), y.push_back(r.rmse), t.push_back(r.cpu_seconds);
        // Without the sampler's share: the cost of the paths the pattern drives.
        t_net.push_back(r.cpu_seconds * (1 - (std::isfinite(r.profile.share()) ? r.profile.share() : 0.0)));
        total += r.profile;
      }
    slopes[name] = loglog_slope(x, y);
    t_lo = std::max(t_lo, t.front()), t_hi = std::min(t_hi, t.back());
    by_time[name] = {t, y};
    by_time_net[name] = {t_net, y};
    cost[name] = profile_json(total);
  }
  j["slopes"] = slopes;
  j["sampler_share"] = cost;
  std::vector<double> grid;
  if (t_hi > t_lo && t_lo > 0)
    for (int i = 0; i < 8; ++i) grid.push_back(t_lo * std::pow(t_hi / t_lo, i / 7.0));
  eq_time["seconds"] = grid;
  eq_time["clock"] = "CPU seconds of the render (user + sys), without the scene build";
  for (const auto& [name, ty] : by_time) {
    std::vector<double> v;
    for (double g : grid) v.push_back(loglog_interp(ty.first, ty.second, g));
    eq_time["rmse"][name] = v;
    std::vector<double> w;
    for (double g : grid) w.push_back(loglog_interp(by_time_net[name].first, ty.second, g));
    eq_time["rmse_without_sampler"][name] = w;
  }
  eq_time["without_sampler"] = "CPU seconds less the sampler's share (sampler_share): what the paths cost";
  j["equal_time"] = eq_time;

  // Adaptive refinement: a threshold sweep per sampler, each run compared with uniform
  // sampling at equal samples, and the samples needed to reach the uniform RMSE at the
  // target spp. The default threshold's run also gets its image and sample-count map.
  if (o.adaptive) {
    json ja = json::array(), sweep = json::array(), target;
    std::vector<std::string> csv;
    for (const auto& name : o.samplers) {
      const AdaptiveDesc ad = sweep_adaptive(base, o);
      std::vector<double> x, y;
      const Run* at_target = nullptr;
      for (const Run& u : runs)
        if (u.sampler == name) {
          x.push_back(u.spp_mean), y.push_back(u.rmse);  // traced, like the adaptive mean
          if (u.spp == o.adaptive_target_spp) at_target = &u;
        }
      std::vector<double> cost, err;
      // k = -4..4, and on (up to 8) while even the cheapest run reaches the target, so that
      // the crossing is interpolated rather than only bounded.
      for (int k = kSweepFirstStep; k <= kSweepLastStep; ++k) {
        if (k > kSweepAlwaysLastStep && !cost_to_reach(cost, err, at_target->rmse).upper_bound) break;
        const double threshold = sweep_threshold(base, o, k);
        CompareJob jb;
        jb.kind = CompareJob::Kind::Adaptive, jb.sampler = name, jb.sweep_step = k;
        const CompareRender r = get(jb);
        const double e = corrected_rmse(r.image), uniform = loglog_interp(x, y, r.spp_mean);
        cost.push_back(double(r.samples)), err.push_back(e);
        sweep.push_back({{"sampler", name},
                         {"threshold", threshold},
                         {"samples", r.samples},
                         {"spp_mean", r.spp_mean},
                         {"rmse", e},
                         {"rounds", r.adaptive_rounds},
                         {"seconds", r.seconds}});
        char row[200];
        std::snprintf(row, sizeof row, "%s,%s,%s,%.9g,%lld,%.6g,%.9g,%d,%.4g", name.c_str(), ad.metric.c_str(),
                      ad.variance.c_str(), threshold, (long long)r.samples, r.spp_mean, e,
                      r.adaptive_rounds, r.seconds);
        csv.push_back(row);
        char buf[200];
        std::snprintf(buf, sizeof buf, "%-8s adaptive t=%.5g: %.1f spp mean, rmse %.5f (uniform at equal samples %.5f)",
                      name.c_str(), threshold, r.spp_mean, e, uniform);
        say(buf);
        if (k != 0) continue;
        std::string img = "images/" + name + "-adaptive.png", map = "images/" + name + "-adaptive-samples.png";
        write_display_png(o.out / img, W, H, display_rgb(r.image));
        std::vector<float> rgb(std::size_t(3) * W * H);
        for (std::size_t i = 0; i < r.image.samples.size(); ++i) {
          float t = std::log2(std::max(1.0f, r.image.samples[i])) / std::log2(float(ad.max_spp));
          Vec3 col = heat(t);
          rgb[3 * i] = col.x, rgb[3 * i + 1] = col.y, rgb[3 * i + 2] = col.z;
        }
        write_display_png(o.out / map, W, H, rgb);
        ja.push_back({{"sampler", name},
                      {"metric", ad.metric},
                      {"variance", ad.variance},
                      {"threshold", threshold},
                      {"min_spp", ad.min_spp},
                      {"max_spp", ad.max_spp},
                      {"rounds", r.adaptive_rounds},
                      {"spp_mean", r.spp_mean},
                      {"samples", r.samples},
                      {"seconds", r.seconds},
                      {"rmse", e},
                      {"uniform_rmse_at_equal_samples", std::isnan(uniform) ? json(nullptr) : json(uniform)},
                      {"image", img},
                      {"sample_map", map},
                      {"sample_map_scale", "log2(samples) / log2(max_spp)"}});
      }
      // Traced samples on both sides: the filter's support skips the same share of either.
      const CostToReach c = cost_to_reach(cost, err, at_target->rmse);
      const double ratio = c.cost / double(at_target->samples);
      target[name] = {{"uniform_samples", at_target->samples},
                      {"uniform_rmse", at_target->rmse},
                      {"adaptive_samples", std::isnan(c.cost) ? json(nullptr) : json(c.cost)},
                      {"ratio", std::isnan(ratio) ? json(nullptr) : json(ratio)},
                      {"upper_bound", c.upper_bound}};
      char buf[200];
      if (std::isnan(ratio))  // the report's "not reached": no sweep step got down to it
        std::snprintf(buf, sizeof buf, "%-8s adaptive does not reach the uniform %d-spp RMSE %.5f in its sweep",
                      name.c_str(), o.adaptive_target_spp, at_target->rmse);
      else
        std::snprintf(buf, sizeof buf, "%-8s adaptive reaches the uniform %d-spp RMSE %.5f with %s%.3f of its samples",
                      name.c_str(), o.adaptive_target_spp, at_target->rmse, c.upper_bound ? "<= " : "", ratio);
      say(buf);
    }
    j["adaptive"] = ja;
    j["adaptive_sweep"] = sweep;
    j["adaptive_target"] = {{"spp", o.adaptive_target_spp}, {"samplers", target}};
    j["adaptive_csv"] = "adaptive.csv";
    j["adaptive_plot"] = "adaptive_vs_spp.png";
    write_file_atomically(o.out / "adaptive.csv", [&](std::ostream& os) {
      os << "sampler,metric,variance,threshold,samples,spp_mean,rmse,rounds,seconds\n";
      for (const auto& row : csv) os << row << "\n";
    });
  }

  // One row per seed, with the (sampler, spp) statistics repeated, so a figure can be
  // regenerated from the CSV alone.
  write_file_atomically(o.out / "results.csv", [&](std::ostream& os) {
    os.precision(9);
    os << "sampler,spp,seed_index,seed,samples,seconds,render_seconds,cpu_seconds,mse,rmse,relmse,"
          "rmse_mean,rmse_ci95,bias2,variance,reference_variance,profile_ticks,sampler_ticks\n";
    for (const Run& r : runs)
      for (std::size_t k = 0; k < r.seeds.size(); ++k) {
        const SeedRun& sr = r.seeds[k];
        os << r.sampler << "," << r.spp << "," << k << "," << sr.seed << "," << sr.samples << "," << sr.seconds << ","
           << sr.render_seconds << "," << sr.cpu_seconds << "," << r.stats.mse[k] << "," << r.stats.rmse[k] << ","
           << sr.relmse << "," << r.rmse << "," << r.stats.rmse_ci95 << "," << r.stats.bias2 << ","
           << r.stats.variance << "," << ref_var << "," << sr.profile.ticks << "," << sr.profile.sampler_ticks << "\n";
      }
  });
  fs::path results = o.out / "results.json";
  write_file_atomically(results, [&](std::ostream& os) { os << j.dump(1) << "\n"; });
  return results;
}

fs::path run_compare(const SceneDesc& base, const CompareOptions& o) {
  return write_compare_report(base, o, [&](const CompareJob& job) { return render_job(base, o, job); });
}

}  // namespace pdrt
