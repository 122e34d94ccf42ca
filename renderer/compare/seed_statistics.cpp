#include "renderer/compare/seed_statistics.h"

#include "sampling/core/rng.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pdrt {

uint64_t compare_seed(uint64_t scene_seed, int k) {
  return k == 0 ? scene_seed : hash_combine(scene_seed, 0x636f6d7061726500ull + uint64_t(k));
}

ReferenceNoise reference_noise(const Image& a, int na, const Image& b, int nb) {
  if (a.rgb.size() != b.rgb.size() || a.rgb.empty()) throw std::invalid_argument("half references differ in size");
  const double n = double(na) + nb, w = double(na) * nb / (n * n), N = double(a.rgb.size());
  double s = 0, s2 = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    double d = double(a.rgb[i]) - b.rgb[i];
    d = d * d * w;
    s += d, s2 += d * d;
  }
  ReferenceNoise r;
  r.variance = s / N;
  const double var_d = std::max(0.0, s2 / N - r.variance * r.variance) * N / std::max(1.0, N - 1);
  r.correction_se = std::sqrt(2 * var_d / N);
  return r;
}

double student_t95(int dof) {
  if (dof < 1) throw std::invalid_argument("student_t95: dof must be >= 1");
  // Tabulated t_{0.975} for 1..30 degrees of freedom; beyond, the Cornish-Fisher expansion
  // about z = 1.959964 (Abramowitz & Stegun 26.7.5), accurate to 1e-5 there.
  static constexpr double kTable[30] = {12.7062, 4.30265, 3.18245, 2.77645, 2.57058, 2.44691, 2.36462, 2.30600,
                                        2.26216, 2.22814, 2.20099, 2.17881, 2.16037, 2.14479, 2.13145, 2.11991,
                                        2.10982, 2.10092, 2.09302, 2.08596, 2.07961, 2.07387, 2.06866, 2.06390,
                                        2.05954, 2.05553, 2.05183, 2.04841, 2.04523, 2.04227};
  if (dof <= 30) return kTable[dof - 1];
  const double z = 1.959963985, z2 = z * z, n = dof;
  return z + z * (z2 + 1) / (4 * n) + z * ((5 * z2 + 16) * z2 + 3) / (96 * n * n) +
         z * (((3 * z2 + 19) * z2 + 17) * z2 - 15) / (384 * n * n * n);
}

SeedMean seed_mean(const std::vector<double>& v) {
  if (v.empty()) throw std::invalid_argument("seed_mean: no seeds");
  const std::size_t K = v.size();
  SeedMean m;
  for (double x : v) m.mean += x / double(K);
  if (K > 1) {
    double s2 = 0;
    for (double x : v) s2 += (x - m.mean) * (x - m.mean);
    m.ci95 = student_t95(int(K) - 1) * std::sqrt(s2 / double(K - 1) / double(K));
  }
  return m;
}

SeedStatistics seed_statistics(const std::vector<Image>& seeds, const Image& ref, const ReferenceNoise& noise) {
  const double ref_var = noise.variance;
  if (seeds.empty()) throw std::invalid_argument("seed_statistics: no images");
  for (const Image& im : seeds)
    if (im.rgb.size() != ref.rgb.size() || ref.rgb.empty())
      throw std::invalid_argument("seed_statistics: images differ in size");
  const std::size_t K = seeds.size(), N = ref.rgb.size();
  SeedStatistics st;
  st.mse.assign(K, 0.0);
  double dev2 = 0, var = 0;
  for (std::size_t i = 0; i < N; ++i) {
    double mean = 0;
    for (std::size_t k = 0; k < K; ++k) {
      double d = double(seeds[k].rgb[i]) - ref.rgb[i];
      st.mse[k] += d * d;
      mean += seeds[k].rgb[i];
    }
    mean /= double(K);
    dev2 += (mean - ref.rgb[i]) * (mean - ref.rgb[i]);
    if (K > 1) {
      double s = 0;
      for (std::size_t k = 0; k < K; ++k) s += (seeds[k].rgb[i] - mean) * (seeds[k].rgb[i] - mean);
      var += s / double(K - 1);
    }
  }
  st.variance = var / double(N);
  st.bias2 = dev2 / double(N) - st.variance / double(K) - ref_var;
  for (std::size_t k = 0; k < K; ++k) {
    st.mse[k] = st.mse[k] / double(N) - ref_var;
    st.rmse.push_back(std::sqrt(std::max(0.0, st.mse[k])));
    st.mse_mean += st.mse[k] / double(K);
    st.rmse_mean += st.rmse[k] / double(K);
  }
  const double ref_term = st.rmse_mean > 0 ? noise.correction_se / (2 * st.rmse_mean) : 0.0;
  // The seeds' part has K - 1 degrees of freedom; the reference's is estimated from every
  // pixel, so it takes the normal quantile.
  const double seeds_part = seed_mean(st.rmse).ci95;
  const double ref_part = 1.959964 * ref_term;
  st.rmse_ci95 = std::sqrt(seeds_part * seeds_part + ref_part * ref_part);
  return st;
}

}  // namespace pdrt
