#include "sampling/samplers/sampler_profile.h"

#include <sys/time.h>

#include <cmath>
#include <limits>
#include <mutex>

namespace pdrt {

constinit thread_local volatile std::sig_atomic_t g_in_sampler __attribute__((tls_model("initial-exec"))) = 0;

namespace {

std::atomic<bool> g_live{false};
std::atomic<int64_t> g_ticks{0}, g_sampler_ticks{0};
static_assert(std::atomic<int64_t>::is_always_lock_free, "the handler needs lock-free counters");

void on_tick(int) {
  if (!g_live.load(std::memory_order_relaxed)) return;  // a tick delivered after the timer stopped
  g_ticks.fetch_add(1, std::memory_order_relaxed);
  if (g_in_sampler) g_sampler_ticks.fetch_add(1, std::memory_order_relaxed);
}

void set_timer(long usec) {
  itimerval t{};
  t.it_interval.tv_usec = usec;
  t.it_value.tv_usec = usec;
  setitimer(ITIMER_PROF, &t, nullptr);
}

}  // namespace

double SamplerProfile::share() const {
  return ticks > 0 ? double(sampler_ticks) / double(ticks) : std::numeric_limits<double>::quiet_NaN();
}

double SamplerProfile::standard_error() const {
  const double s = share();
  return ticks > 0 ? std::sqrt(s * (1 - s) / double(ticks)) : std::numeric_limits<double>::quiet_NaN();
}

nlohmann::json profile_json(const SamplerProfile& p) {
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"share", number(p.share())},
          {"standard_error", number(p.standard_error())},
          {"ticks", p.ticks},
          {"sampler_ticks", p.sampler_ticks}};
}

SamplerProfiler::SamplerProfiler() {
  bool expected = false;
  if (!g_live.compare_exchange_strong(expected, true)) return;
  // The handler stays installed for good: a SIGPROF still pending when the timer stops must
  // not meet the default action, which ends the process.
  static std::once_flag installed;
  std::call_once(installed, [] {
    struct sigaction sa {};
    sa.sa_handler = on_tick;
    sa.sa_flags = SA_RESTART;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGPROF, &sa, nullptr);
  });
  g_ticks = 0, g_sampler_ticks = 0;
  active_ = true;
  set_timer(1000);
}

SamplerProfile SamplerProfiler::peek() const {
  if (!active_) return result_;
  SamplerProfile p;
  p.ticks = g_ticks.load(), p.sampler_ticks = g_sampler_ticks.load();
  return p;
}

SamplerProfile SamplerProfiler::result() {
  if (active_) {
    set_timer(0);
    result_.ticks = g_ticks.load(), result_.sampler_ticks = g_sampler_ticks.load();
    active_ = false;
    g_live = false;
  }
  return result_;
}

SamplerProfiler::~SamplerProfiler() { result(); }

}  // namespace pdrt
