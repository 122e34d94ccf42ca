#pragma once
// Integration error of a sampler on the standard 2-D test integrands (disk, triangle, step,
// Gaussian, bilinear), the measure behind docs/sampling.md's sampler comparison. Each trial
// is one pixel's sample stream of a family, so trials are independent streams of the sampler.
#include "sampling/samplers/sampler.h"

#include <string>
#include <vector>

namespace pdrt {

struct Integrand {
  std::string name;
  double (*f)(Vec2);
  double exact;
};

const std::vector<Integrand>& standard_integrands();

// RMS error of the N-sample estimate over `trials` pixels (pixel (t mod 64, t / 64)).
double integration_rmse(const Sampler& s, const Integrand& f, int64_t n, int trials, Family family = Family::Lens);

// The same for 1-D integrands on the time family: a step (a moving edge's coverage) and a
// smooth exponential (a shutter-weighted fade).
struct Integrand1D {
  std::string name;
  double (*f)(double);
  double exact;
};
const std::vector<Integrand1D>& time_integrands();
double integration_rmse_1d(const Sampler& s, const Integrand1D& f, int64_t n, int trials);

}  // namespace pdrt
