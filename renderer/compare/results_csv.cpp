#include "renderer/compare/results_csv.h"

#include "sampling/core/atomic_file.h"

namespace pdrt {

void write_results_csv(const ReportContext& ctx, const CompareResults& results) {
  const double ref_var = results.reference.noise.variance;
  write_file_atomically(ctx.o.out / "results.csv", [&](std::ostream& os) {
    os.precision(9);
    os << "sampler,spp,seed_index,seed,samples,seconds,render_seconds,cpu_seconds,mse,rmse,relmse,"
          "rmse_mean,rmse_ci95,bias2,variance,reference_variance,profile_ticks,sampler_ticks\n";
    for (const UniformRun& r : results.runs)
      for (std::size_t k = 0; k < r.seeds.size(); ++k) {
        const SeedRun& sr = r.seeds[k];
        os << r.sampler << "," << r.spp << "," << k << "," << sr.seed << "," << sr.samples << "," << sr.seconds << ","
           << sr.render_seconds << "," << sr.cpu_seconds << "," << r.stats.mse[k] << "," << r.stats.rmse[k] << ","
           << sr.relmse << "," << r.rmse << "," << r.stats.rmse_ci95 << "," << r.stats.bias2 << ","
           << r.stats.variance << "," << ref_var << "," << sr.profile.ticks << "," << sr.profile.sampler_ticks << "\n";
      }
  });
}

}  // namespace pdrt
