// Integration error report (issue 3): RMSE of every sampler on the standard 2-D integrands
// (lens family) and two 1-D ones (time family) at N = 16..4096, over 256 independent pixel
// streams, and the log-log slope of RMSE vs N.
// Not a timed test: run ./build/bench/integration_report and read the tables it prints.
#include "sampling/analysis/integration_error.h"
#include "sampling/generators/stratified_best_candidate_1d.h"
#include "sampling/samplers/poisson_sampler.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace pdrt;

namespace {

// The default tables with the time family replaced by stratified-bc sets of the same size
// (issue 16's stratified 1-D variant; in memory only, the table format does not name it yet).
TableSet with_stratified_time_tables(int candidates) {
  TableSet set = default_tables();
  const SampleTable& balanced = *set.family[int(Family::Time)];
  auto t = std::make_shared<SampleTable>();
  t->params = balanced.params;
  t->dim = 1;
  for (uint32_t k = 0; k < balanced.table_count(); ++k) {
    StratifiedBestCandidate1D p;
    p.count = balanced.params.points, p.seed = 1000 + k, p.candidates = candidates;
    const PointSet ps = stratified_best_candidate_1d(p);
    std::vector<uint32_t> c;
    std::vector<float> r;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      c.push_back(uint32_t(std::min(std::floor(ps.coords[i] * 4294967296.0), 4294967295.0)));
      r.push_back(float(ps.radius[i]));
    }
    t->coords.push_back(std::move(c));
    t->radius.push_back(std::move(r));
  }
  set.family[int(Family::Time)] = t;
  return set;
}

}  // namespace

int main() {
  const int trials = 256;
  const std::vector<int64_t> ns = {16, 64, 256, 1024, 4096};
  struct Entry {
    std::string label;
    std::unique_ptr<Sampler> s;
  };
  std::vector<Entry> samplers;
  for (const char* name : {"random", "jitter", "sobol"}) samplers.push_back({name, make_sampler(name, 1)});
  samplers.push_back({"poisson", make_poisson_sampler(1, default_tables())});
  samplers.push_back({"poisson-noshift", make_poisson_sampler(1, default_tables(), {.toroidal_shift = false})});
  // A toroidal shift keeps a stratified set stratified only on the circle: the stratum across
  // 0/1 sees a non-periodic integrand's jump, so the shifted row converges at -1.0, not -1.5.
  const TableSet stratified = with_stratified_time_tables(16);
  samplers.push_back({"poisson, stratified-bc time", make_poisson_sampler(1, stratified)});
  samplers.push_back({"poisson-noshift, stratified-bc time", make_poisson_sampler(1, stratified, {.toroidal_shift = false})});
  const int64_t table_len = default_tables().family[int(Family::Lens)]->params.points;
  std::printf("Lens family, %d pixels per point; RMSE (slope of log RMSE vs log N over 16..1024)\n", trials);
  std::printf("poisson beyond N = %lld continues in another table and is no longer one prefix.\n\n",
              (long long)table_len);
  // One table: a row per sampler, RMSE at every N and the slope over 16..1024.
  auto table = [&](const std::string& title, auto&& rmse) {
    std::printf("### %s\n\n| sampler |", title.c_str());
    for (int64_t n : ns) std::printf(" N=%lld |", (long long)n);
    std::printf(" slope |\n|---|");
    for (std::size_t i = 0; i <= ns.size(); ++i) std::printf("---|");
    std::printf("\n");
    for (const Entry& e : samplers) {
      std::printf("| %s |", e.label.c_str());
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      int m = 0;
      for (int64_t n : ns) {
        double r = rmse(*e.s, n);
        std::printf(" %.3g |", r);
        if (n <= 1024) {
          double x = std::log(double(n)), y = std::log(r);
          sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
        }
      }
      std::printf(" %.2f |\n", (m * sxy - sx * sy) / (m * sxx - sx * sx));
    }
    std::printf("\n");
  };
  for (const Integrand& f : standard_integrands())
    table(f.name + " (exact " + std::to_string(f.exact) + ")",
          [&](const Sampler& s, int64_t n) { return integration_rmse(s, f, n, trials); });
  std::printf("Time family (1-D), %d pixels per point.\n\n", trials);
  for (const Integrand1D& f : time_integrands())
    table("time " + f.name + " (exact " + std::to_string(f.exact) + ")",
          [&](const Sampler& s, int64_t n) { return integration_rmse_1d(s, f, n, trials); });
}
