#include "renderer/compare/results_csv.h"

#include "sampling/core/atomic_file.h"

namespace pdrt {

namespace {

static_assert(kBlurSigmas.size() == 2, "results.csv names the blurred RMSE columns s1 and s2");

// Seed k's screen-space measures and their runs' means and half widths, each preceded by a comma.
void write_screen_columns(std::ostream& os, const ScreenMeasures& m, std::size_t k) {
  for (const SeedStatistics& st : m.blurred) os << "," << st.rmse[k] << "," << st.rmse_mean << "," << st.rmse_ci95;
  os << "," << m.low_share[k] << "," << m.low_share_mean.mean << "," << m.low_share_mean.ci95;
  os << "," << m.flip_ldr[k] << "," << m.flip_ldr_mean.mean << "," << m.flip_ldr_mean.ci95;
  os << "," << m.flip_hdr[k] << "," << m.flip_hdr_mean.mean << "," << m.flip_hdr_mean.ci95;
}

}  // namespace

void write_results_csv(const ReportContext& ctx, const CompareResults& results) {
  const double ref_var = results.reference.noise.variance;
  write_file_atomically(ctx.o.out / "results.csv", [&](std::ostream& os) {
    os.precision(9);
    os << "sampler,spp,seed_index,seed,samples,seconds,render_seconds,cpu_seconds,mse,rmse,relmse,"
          "rmse_mean,rmse_ci95,bias2,variance,reference_variance,profile_ticks,sampler_ticks,"
          "blurred_rmse_s1,blurred_rmse_s1_mean,blurred_rmse_s1_ci95,blurred_rmse_s2,blurred_rmse_s2_mean,"
          "blurred_rmse_s2_ci95,low_frequency_share,low_frequency_share_mean,low_frequency_share_ci95,"
          "flip_ldr,flip_ldr_mean,flip_ldr_ci95,flip_hdr,flip_hdr_mean,flip_hdr_ci95\n";
    for (const UniformRun& r : results.runs)
      for (std::size_t k = 0; k < r.seeds.size(); ++k) {
        const SeedRun& sr = r.seeds[k];
        os << r.sampler << "," << r.spp << "," << k << "," << sr.seed << "," << sr.samples << "," << sr.seconds << ","
           << sr.render_seconds << "," << sr.cpu_seconds << "," << r.stats.mse[k] << "," << r.stats.rmse[k] << ","
           << sr.relmse << "," << r.rmse << "," << r.stats.rmse_ci95 << "," << r.stats.bias2 << "," << r.stats.variance
           << "," << ref_var << "," << sr.profile.ticks << "," << sr.profile.sampler_ticks;
        write_screen_columns(os, r.screen, k);
        os << "\n";
      }
  });
}

}  // namespace pdrt
