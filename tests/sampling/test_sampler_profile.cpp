// The sampling profiler behind the sampler's share of render time: CPU spent inside a
// SamplerScope counts as the sampler's, CPU outside it does not.
#include "sampling/samplers/sampler_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ctime>

namespace pdrt {
namespace {

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Burns `seconds` of this thread's CPU, inside a SamplerScope for the first `inside` of them.
double burn(double seconds, double inside) {
  volatile double x = 1.0;
  const double t0 = thread_cpu_seconds();
  while (thread_cpu_seconds() - t0 < seconds) {
    const bool in = thread_cpu_seconds() - t0 < inside;
    if (in) {
      SamplerScope scope;
      for (int i = 0; i < 1000; ++i) x = x * 1.0000001 + 1e-9;
    } else {
      for (int i = 0; i < 1000; ++i) x = x * 1.0000001 + 1e-9;
    }
  }
  return x;
}

TEST(SamplerProfiler, CountsTheShareOfCpuInsideSamplerScopes) {
  SamplerProfiler profiler;
  ASSERT_TRUE(profiler.active());
  burn(0.6, 0.15);  // a quarter inside
  const SamplerProfile p = profiler.result();
  // At the kernel's tick (1-4 ms) 0.6 s gives 150-600 ticks; the share's standard error is
  // then at most 0.035, so 4 of them is 0.14.
  ASSERT_GT(p.ticks, 100);
  EXPECT_NEAR(p.share(), 0.25, std::max(0.08, 4 * p.standard_error())) << p.sampler_ticks << " of " << p.ticks;
  EXPECT_FALSE(profiler.active());
}

TEST(SamplerProfiler, OnlyOneProfilesAtATimeAndNothingCountsAfterIt) {
  SamplerProfiler a;
  SamplerProfiler b;
  EXPECT_TRUE(a.active());
  EXPECT_FALSE(b.active());
  EXPECT_EQ(b.result().ticks, 0);
  EXPECT_TRUE(std::isnan(b.result().share()));
  const int64_t ticks = a.result().ticks;
  burn(0.1, 0.1);
  EXPECT_EQ(a.result().ticks, ticks);  // stopped: later CPU is not counted
}

}  // namespace
}  // namespace pdrt
