// The sampling profiler behind the sampler's share of render time: CPU spent inside a
// SamplerScope counts as the sampler's, CPU outside it does not.
#include "sampling/samplers/sampler_profile.h"
#include "sampling/core/rng.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ctime>

namespace pdrt {
namespace {

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Burns this thread's CPU in chunks of about 0.2 ms, each inside a SamplerScope with
// probability `inside` (random, so no chunk pattern can lock to the kernel's tick), until
// `done()` or `limit` seconds of CPU.
template <class Done>
double burn(double inside, double limit, Done&& done) {
  volatile double x = 1.0;
  Rng rng(11);
  const double t0 = thread_cpu_seconds();
  while (!done() && thread_cpu_seconds() - t0 < limit) {
    // The whole chunk, clock reads included, is inside or outside.
    auto chunk = [&] {
      const double c0 = thread_cpu_seconds();
      while (thread_cpu_seconds() - c0 < 2e-4)
        for (int i = 0; i < 200; ++i) x = x * 1.0000001 + 1e-9;
    };
    if (rng.uniform() < inside) {
      SamplerScope scope;
      chunk();
    } else {
      chunk();
    }
  }
  return x;
}

// A quarter of the CPU inside: the share is 0.25 within 4 standard errors of the ticks'
// binomial noise (at least 300 ticks, so 4 SE <= 0.1). The kernel delivers at most one tick per
// scheduler tick, fewer on a busy machine, so the test burns until it has them.
TEST(SamplerProfiler, CountsTheShareOfCpuInsideSamplerScopes) {
  SamplerProfiler profiler;
  ASSERT_TRUE(profiler.active());
  burn(0.25, 30.0, [&] { return profiler.peek().ticks >= 300; });
  const SamplerProfile p = profiler.result();
  ASSERT_GE(p.ticks, 300) << "the profiler's ticks did not arrive";
  std::printf("profiler: %lld of %lld ticks inside, share %.3f +- %.3f (true 0.25)\n", (long long)p.sampler_ticks,
              (long long)p.ticks, p.share(), p.standard_error());
  EXPECT_NEAR(p.share(), 0.25, 4 * p.standard_error()) << p.sampler_ticks << " of " << p.ticks;
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
  burn(1.0, 0.1, [] { return false; });
  EXPECT_EQ(a.result().ticks, ticks);  // stopped: later CPU is not counted
}

}  // namespace
}  // namespace pdrt
