// Robust facts of the sampler comparison (the full numbers are in docs/sampling.md).
#include "sampling/analysis/integration_error.h"
#include "sampling/samplers/poisson_sampler.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pdrt {
namespace {

TEST(IntegrationError, PoissonBeatsRandomAtSixtyFourSamples) {
  auto poisson = make_poisson_sampler(1, default_tables());
  auto random = make_sampler("random", 1);
  for (const Integrand& f : standard_integrands())
    EXPECT_LT(integration_rmse(*poisson, f, 64, 256), integration_rmse(*random, f, 64, 256)) << f.name;
}

TEST(IntegrationError, JitterAndSobolConvergeFasterThanRandomOnSmoothIntegrands) {
  // Stratified patterns have error O(N^-1) on smooth integrands, random O(N^-1/2): from 64
  // to 1024 samples the RMSE of jitter and sobol must fall by more than 8x, random's by 4x.
  const Integrand& g = standard_integrands()[3];  // gaussian
  for (const char* name : {"jitter", "sobol"}) {
    auto s = make_sampler(name, 1);
    EXPECT_GT(integration_rmse(*s, g, 64, 256) / integration_rmse(*s, g, 1024, 256), 8.0) << name;
  }
}

TEST(IntegrationError, ExactValuesOfTheIntegrandsAreRight) {
  // A dense midpoint rule agrees with every closed form to 1e-3.
  for (const Integrand& f : standard_integrands()) {
    double sum = 0.0;
    const int m = 1000;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) sum += f.f({(i + 0.5) / m, (j + 0.5) / m});
    EXPECT_NEAR(sum / (double(m) * m), f.exact, 1e-3) << f.name;
  }
}

TEST(IntegrationError, ExactValuesOfTheTimeIntegrandsAreRight) {
  // A dense midpoint rule agrees with both closed forms to 1e-5.
  for (const Integrand1D& f : time_integrands()) {
    double sum = 0.0;
    const int m = 200000;
    for (int i = 0; i < m; ++i) sum += f.f((i + 0.5) / m);
    EXPECT_NEAR(sum / m, f.exact, 1e-5) << f.name;
  }
}

TEST(IntegrationError, RandomTimeSamplesHaveMonteCarloError) {
  // Independent uniform samples: RMSE = sqrt(p (1 - p) / N) for the step. Over 256 trials
  // the RMSE's relative spread is ~4.4 %; 15 % is over three of those.
  auto random = make_sampler("random", 1);
  const Integrand1D& step = time_integrands()[0];
  const double expected = std::sqrt(step.exact * (1 - step.exact) / 256);
  EXPECT_NEAR(integration_rmse_1d(*random, step, 256, 256), expected, 0.15 * expected);
}

}  // namespace
}  // namespace pdrt
