#pragma once
// The sampler's share of a render's CPU time, measured by a sampling profiler: while a
// SamplerProfiler is live, SIGPROF fires every millisecond of process CPU time (ITIMER_PROF,
// user + sys of all threads) and lands on the thread that used it; the tick counts as the
// sampler's when that thread is inside a PixelSampleState call (SamplerScope). The share is
// unbiased, its standard error sqrt(s (1 - s) / ticks); the cost is two stores per call.
#include <nlohmann/json.hpp>

#include <atomic>
#include <csignal>
#include <cstdint>

namespace pdrt {

// Set while this thread computes sample values. initial-exec: a plain fs-relative store
// (pdrt's libraries are linked statically, never dlopen'ed).
extern thread_local constinit volatile std::sig_atomic_t g_in_sampler __attribute__((tls_model("initial-exec")));

struct SamplerScope {
  SamplerScope() {
    g_in_sampler = 1;
    std::atomic_signal_fence(std::memory_order_seq_cst);  // the work stays inside the flag
  }
  ~SamplerScope() {
    std::atomic_signal_fence(std::memory_order_seq_cst);
    g_in_sampler = 0;
  }
  SamplerScope(const SamplerScope&) = delete;
  SamplerScope& operator=(const SamplerScope&) = delete;
};

struct SamplerProfile {
  int64_t ticks = 0;                                     // CPU milliseconds sampled
  int64_t sampler_ticks = 0;                             // of which inside the sampler
  double share() const;                                  // sampler_ticks / ticks; NaN without ticks
  SamplerProfile& operator+=(const SamplerProfile& o) {  // pooling runs (seeds, spp)
    ticks += o.ticks, sampler_ticks += o.sampler_ticks;
    return *this;
  }
  double standard_error() const;
};

// {share, standard_error (null without ticks), ticks, sampler_ticks}, as render --stats and
// compare's results.json write it.
nlohmann::json profile_json(const SamplerProfile& p);

// Profiles from construction to result(). One at a time per process: a profiler made while
// another is live is inactive and reports no ticks.
class SamplerProfiler {
 public:
  SamplerProfiler();
  ~SamplerProfiler();
  SamplerProfiler(const SamplerProfiler&) = delete;
  SamplerProfiler& operator=(const SamplerProfiler&) = delete;
  bool active() const { return active_; }
  SamplerProfile peek() const;  // the counts so far, still profiling
  SamplerProfile result();      // stops the timer

 private:
  bool active_ = false;
  SamplerProfile result_;
};

}  // namespace pdrt
