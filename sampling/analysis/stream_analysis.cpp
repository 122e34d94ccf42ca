#include "sampling/analysis/stream_analysis.h"

#include "sampling/measures/min_distance.h"
#include "sampling/analysis/periodogram.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pdrt {

StreamAnalysis analyze_stream(const Sampler& sampler, Family family, int width, int height, int spp, int max_pixels) {
  StreamAnalysis a;
  a.family = family, a.spp = spp;
  a.periodic = family != Family::Pixel;  // a pixel's offsets are a window of the image plane, not a torus
  const int64_t total = int64_t(width) * height;
  const int64_t n_sets = std::max<int64_t>(1, std::min<int64_t>(max_pixels, total));
  const int dim = family_dim(family);
  std::vector<PointSet> sets(static_cast<std::size_t>(n_sets));
  std::vector<double> rho;
  for (int64_t k = 0; k < n_sets; ++k) {
    const int64_t p = k * total / n_sets;
    const int px = int(p % width), py = int(p / width);
    PointSet& s = sets[std::size_t(k)];
    s.dim = dim, s.periodic = a.periodic;
    s.coords.reserve(std::size_t(spp) * dim);
    for (int i = 0; i < spp; ++i) {
      if (dim == 1) {
        s.coords.push_back(sampler.get_1d(px, py, i, family, 0));
      } else {
        const Vec2 v = sampler.get_2d(px, py, i, family, 0);
        s.coords.push_back(v[0]), s.coords.push_back(v[1]);
      }
    }
    if (spp >= 2) rho.push_back(relative_radius(min_distance(s, a.periodic), s.size(), dim));
  }
  a.pixels = int(n_sets);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  a.rho_mean = a.rho_p05 = a.rho_min = nan;
  if (!rho.empty()) {
    std::sort(rho.begin(), rho.end());
    double sum = 0;
    for (double r : rho) sum += r;
    a.rho_mean = sum / double(rho.size());
    a.rho_p05 = rho[std::size_t(0.05 * double(rho.size() - 1))];
    a.rho_min = rho.front();
  }
  a.resolution = default_periodogram_resolution(dim == 1 ? 1 : 2, spp);
  a.spectrum = fine_annuli(compute_periodogram(sets, a.resolution), 64);
  return a;
}

}  // namespace pdrt
