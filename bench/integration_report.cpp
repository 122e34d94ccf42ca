// Integration error report (issues 3, 16): RMSE of every sampler on the standard 2-D
// integrands (lens family) and two 1-D ones (time family) at N = 16..2048, over 1024
// independent pixel streams, the log-log slope of RMSE vs N over 16..1024, and the relative
// radius rho of the streams' prefixes (mean over the same pixels) beside them.
// Not a timed test: run ./build/bench/integration_report and read the tables it prints.
#include "sampling/analysis/integration_error.h"
#include "sampling/analysis/stream_analysis.h"
#include "sampling/samplers/poisson_sampler.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <memory>
#include <vector>

using namespace pdrt;

namespace {

// The `poisson-065` set as it was before issue 16: McCool–Fiume relaxation tables of 1024
// points for the 2-D families (built in memory), balanced time tables.
TableSet mccool_tables() {
  TableSet set = default_tables(TableSetKind::Poisson065);
  for (Family f : {Family::Pixel, Family::Lens, Family::Light, Family::Gloss}) {
    TableParams p;
    p.family = f, p.construction = Construction::Relaxation, p.points = 1024;
    set.family[int(f)] = std::make_shared<const SampleTable>(generate_table(p));
  }
  return set;
}

}  // namespace

int main() {
  const int trials = 1024;
  const std::vector<int64_t> ns = {16, 32, 64, 128, 256, 512, 1024, 2048};
  const std::vector<int64_t> rho_ns = {16, 64, 256, 1024, 2048};
  struct Entry {
    std::string label;
    std::unique_ptr<Sampler> s;
  };
  std::vector<Entry> samplers;
  for (const char* name : {"random", "jitter", "sobol"}) samplers.push_back({name, make_sampler(name, 1)});
  const TableSet old = mccool_tables();
  samplers.push_back({"poisson (mccool tables, before issue 16)", make_poisson_sampler(1, old)});
  const TableSet& p065 = default_tables(TableSetKind::Poisson065);
  samplers.push_back({"poisson-065", make_poisson_sampler(1, p065)});
  samplers.push_back({"poisson-065, unshifted", make_poisson_sampler(1, p065, {.shift = false})});
  samplers.push_back({"poisson", make_poisson_sampler(1, default_tables())});
  samplers.push_back({"poisson, isometric shifts", make_poisson_sampler(1, default_tables(),
                                                                        {.plane = PoissonShift::Isometric,
                                                                         .pixel = PoissonShift::Isometric,
                                                                         .time = PoissonShift::Isometric})});
  samplers.push_back({"poisson, unshifted", make_poisson_sampler(1, default_tables(), {.shift = false})});
  std::printf(
      "RMSE over %d pixels' streams (slope of log RMSE vs log N over 16..1024); rho: mean relative\n"
      "radius of the same streams' N-point prefixes. Table samplers beyond a table's length continue\n"
      "in another table (no longer one prefix).\n\n",
      trials);
  std::map<std::tuple<std::string, int, int64_t>, double> rho;               // the same for every integrand
  std::map<std::tuple<std::string, std::string, int64_t>, double> measured;  // (integrand, sampler, N)
  std::vector<std::string> titles;
  // One table: a row per sampler, RMSE at every N, the slope over 16..1024, then rho.
  auto table = [&](const std::string& title, Family family, auto&& rmse) {
    titles.push_back(title);
    std::printf("### %s\n\n| sampler |", title.c_str());
    for (int64_t n : ns) std::printf(" N=%lld |", (long long)n);
    std::printf(" slope |");
    for (int64_t n : rho_ns) std::printf(" rho %lld |", (long long)n);
    std::printf("\n|---|");
    for (std::size_t i = 0; i <= ns.size() + rho_ns.size(); ++i) std::printf("---|");
    std::printf("\n");
    for (const Entry& e : samplers) {
      std::printf("| %s |", e.label.c_str());
      double sx = 0, sy = 0, sxx = 0, sxy = 0;
      int m = 0;
      for (int64_t n : ns) {
        double r = rmse(*e.s, n);
        measured[{title, e.label, n}] = r;
        std::printf(" %.3g |", r);
        if (n <= 1024) {
          double x = std::log(double(n)), y = std::log(r);
          sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
        }
      }
      std::printf(" %.2f |", (m * sxy - sx * sy) / (m * sxx - sx * sx));
      for (int64_t n : rho_ns) {
        auto key = std::make_tuple(e.label, int(family), n);
        if (!rho.count(key)) rho[key] = analyze_stream(*e.s, family, 16, 16, int(n), 64).rho_mean;
        std::printf(" %.3f |", rho[key]);
      }
      std::printf("\n");
    }
    std::printf("\n");
  };
  for (const Integrand& f : standard_integrands())
    table(f.name + " (exact " + std::to_string(f.exact) + "), lens family", Family::Lens,
          [&](const Sampler& s, int64_t n) { return integration_rmse(s, f, n, trials); });
  for (const Integrand1D& f : time_integrands())
    table("time " + f.name + " (exact " + std::to_string(f.exact) + "), time family", Family::Time,
          [&](const Sampler& s, int64_t n) { return integration_rmse_1d(s, f, n, trials); });
  // The goals of issues 16 and 28 as ratios of the rows above (< 1: the first sampler's error
  // is lower).
  std::printf(
      "### Ratios (issues 16, 28)\n\n| integrand | poisson-065 / mccool tables at N=1024 | worst poisson / sobol, "
      "N=16..1024 | worst poisson / jitter, N=16..1024 |\n|---|---|---|---|\n");
  for (const std::string& t : titles) {
    double worst_s = 0, worst_j = 0;
    for (int64_t n : ns) {
      if (n > 1024) continue;
      worst_s = std::max(worst_s, measured[{t, "poisson", n}] / measured[{t, "sobol", n}]);
      worst_j = std::max(worst_j, measured[{t, "poisson", n}] / measured[{t, "jitter", n}]);
    }
    std::printf("| %s | %.2f | %.2f | %.2f |\n", t.c_str(),
                measured[{t, "poisson-065", 1024}] / measured[{t, "poisson (mccool tables, before issue 16)", 1024}],
                worst_s, worst_j);
  }
}
