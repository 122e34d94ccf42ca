#include "renderer/compare/convergence_view.h"

#include "renderer/compare/convergence.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pdrt {

ConvergenceView convergence_view(const CompareOptions& o, const std::vector<UniformRun>& runs) {
  ConvergenceView v;
  double t_lo = 0, t_hi = 1e300;
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> by_time, by_time_net;
  for (const auto& name : o.samplers) {
    std::vector<double> x, y, t, t_net;
    SamplerProfile total;
    for (const UniformRun& r : runs)
      if (r.sampler == name) {
        x.push_back(r.spp), y.push_back(r.rmse), t.push_back(r.cpu_seconds);
        // Without the sampler's share: the cost of the paths the pattern drives.
        t_net.push_back(r.cpu_seconds * (1 - (std::isfinite(r.profile.share()) ? r.profile.share() : 0.0)));
        total += r.profile;
      }
    v.slopes[name] = loglog_slope(x, y);
    t_lo = std::max(t_lo, t.front()), t_hi = std::min(t_hi, t.back());
    by_time[name] = {t, y};
    by_time_net[name] = {t_net, y};
    v.sampler_cost[name] = total;
  }
  if (t_hi > t_lo && t_lo > 0)
    for (int i = 0; i < 8; ++i) v.seconds.push_back(t_lo * std::pow(t_hi / t_lo, i / 7.0));
  for (const auto& [name, ty] : by_time) {
    std::vector<double>& rmse = v.rmse[name];
    for (double g : v.seconds) rmse.push_back(loglog_interp(ty.first, ty.second, g));
    std::vector<double>& net = v.rmse_without_sampler[name];
    for (double g : v.seconds) net.push_back(loglog_interp(by_time_net[name].first, ty.second, g));
  }
  return v;
}

}  // namespace pdrt
