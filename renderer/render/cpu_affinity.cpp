#include "renderer/render/cpu_affinity.h"

#include "sampling/core/warnings.h"

#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <memory>
#include <thread>

namespace pdrt {

int allowed_cpus() {
  // A mask as large as the kernel may report (CPU_ALLOC): cpu_set_t alone stops at 1024 CPUs.
  for (int n = 1024; n <= (1 << 20); n *= 2) {
    const std::unique_ptr<cpu_set_t, void (*)(cpu_set_t*)> set(CPU_ALLOC(n), [](cpu_set_t* s) { CPU_FREE(s); });
    const std::size_t bytes = CPU_ALLOC_SIZE(n);
    if (sched_getaffinity(0, bytes, set.get()) == 0) return CPU_COUNT_S(bytes, set.get());
    if (errno != EINVAL) break;
  }
  return std::max(1, int(std::thread::hardware_concurrency()));
}

std::string thread_request_warning(int requested, int allowed) {
  if (requested <= allowed) return "";
  const std::string n = std::to_string(requested), a = std::to_string(allowed);
  return "pdrt: warning: --threads " + n + " but this process may run on " + a + (allowed == 1 ? " CPU" : " CPUs") +
         " (its affinity mask), so it runs " + a + (allowed == 1 ? " thread" : " threads") +
         "; under mpirun give each rank its cores with --bind-to none or --map-by slot:PE=" + n;
}

void warn_thread_request(int requested) {
  static std::atomic<bool> warned{false};
  const std::string line = thread_request_warning(requested, allowed_cpus());
  if (!line.empty() && !warned.exchange(true)) warn(line, "threads above the affinity mask");
}

}  // namespace pdrt
