#include "renderer/compare/adaptive_sweep.h"

#include "renderer/compare/convergence.h"
#include "renderer/compare/heat_maps.h"
#include "sampling/core/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pdrt {

namespace {

// Writes step 0's image and its sample-count map (log2(samples) / log2(max_spp) on the heat ramp).
void write_step_images(const ReportContext& ctx, const AdaptiveDesc& ad, const CompareRender& r, SamplerSweep& s) {
  s.image = "images/" + s.sampler + "-adaptive.png", s.sample_map = "images/" + s.sampler + "-adaptive-samples.png";
  ctx.write_png(s.image, display_rgb(r.image));
  std::vector<float> level(r.image.samples.size());
  for (std::size_t i = 0; i < level.size(); ++i) level[i] = std::log2(std::max(1.0f, r.image.samples[i]));
  std::vector<float> rgb = heat_rgb(level, std::log2(float(ad.max_spp)));
  rgb.resize(std::size_t(3) * ctx.width * ctx.height);  // black where a render has no sample counts
  ctx.write_png(s.sample_map, rgb);
}

SamplerSweep sweep_sampler(const ReportContext& ctx, const CompareResults& results, const std::string& name,
                           const AdaptiveDesc& ad) {
  SamplerSweep s;
  s.sampler = name;
  std::vector<double> x, y;  // the uniform runs' traced spp (like the adaptive mean) and RMSE
  for (std::size_t i = 0; i < results.runs.size(); ++i)
    if (const UniformRun& u = results.runs[i]; u.sampler == name) {
      x.push_back(u.spp_mean), y.push_back(u.rmse);
      if (u.spp == ctx.o.adaptive_target_spp) s.uniform_run = i;
    }
  const UniformRun& at_target = results.runs[s.uniform_run];
  std::vector<double> cost, err;
  for (int k = kSweepFirstStep; k <= kSweepLastStep; ++k) {
    if (k > kSweepAlwaysLastStep && !cost_to_reach(cost, err, at_target.rmse).upper_bound) break;
    SweepStep st;
    st.step = k, st.threshold = sweep_threshold(ctx.base, ctx.o, k);
    CompareJob jb;
    jb.kind = CompareJob::Kind::Adaptive, jb.sampler = name, jb.sweep_step = k;
    st.render = ctx.get(jb);
    st.rmse = results.reference.corrected_rmse(st.render.image);
    st.uniform_rmse = loglog_interp(x, y, st.render.spp_mean);
    cost.push_back(double(st.render.samples)), err.push_back(st.rmse);
    char buf[200];
    std::snprintf(buf, sizeof buf, "%-8s adaptive t=%.5g: %.1f spp mean, rmse %.5f (uniform at equal samples %.5f)",
                  name.c_str(), st.threshold, st.render.spp_mean, st.rmse, st.uniform_rmse);
    ctx.say(buf);
    if (k == 0) write_step_images(ctx, ad, st.render, s);
    st.render.image = Image{};  // not needed any more
    s.steps.push_back(std::move(st));
  }
  // Traced samples on both sides: the filter's support skips the same share of either.
  s.cost = cost_to_reach(cost, err, at_target.rmse);
  s.ratio = s.cost.cost / double(at_target.samples);
  char buf[200];
  if (std::isnan(s.ratio))  // the report's "not reached": no sweep step got down to it
    std::snprintf(buf, sizeof buf, "%-8s adaptive does not reach the uniform %d-spp RMSE %.5f in its sweep",
                  name.c_str(), ctx.o.adaptive_target_spp, at_target.rmse);
  else
    std::snprintf(buf, sizeof buf, "%-8s adaptive reaches the uniform %d-spp RMSE %.5f with %s%.3f of its samples",
                  name.c_str(), ctx.o.adaptive_target_spp, at_target.rmse, s.cost.upper_bound ? "<= " : "", s.ratio);
  ctx.say(buf);
  return s;
}

}  // namespace

void run_adaptive_sweep(const ReportContext& ctx, CompareResults& results) {
  results.adaptive.settings = sweep_adaptive(ctx.base, ctx.o);
  for (const auto& name : ctx.o.samplers)
    results.adaptive.samplers.push_back(sweep_sampler(ctx, results, name, results.adaptive.settings));
}

void write_adaptive_csv(const ReportContext& ctx, const CompareResults& results) {
  const AdaptiveDesc& ad = results.adaptive.settings;
  write_file_atomically(ctx.o.out / "adaptive.csv", [&](std::ostream& os) {
    os << "sampler,metric,variance,threshold,samples,spp_mean,rmse,rounds,seconds\n";
    for (const SamplerSweep& s : results.adaptive.samplers)
      for (const SweepStep& st : s.steps) {
        char row[200];
        std::snprintf(row, sizeof row, "%s,%s,%s,%.9g,%lld,%.6g,%.9g,%d,%.4g", s.sampler.c_str(),
                      adaptive_metric_name(ad.metric), adaptive_variance_name(ad.variance), st.threshold,
                      (long long)st.render.samples, st.render.spp_mean, st.rmse, st.render.adaptive_rounds,
                      st.render.seconds);
        os << row << "\n";
      }
  });
}

}  // namespace pdrt
