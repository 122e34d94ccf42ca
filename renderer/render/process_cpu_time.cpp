#include "renderer/render/process_cpu_time.h"

#include <sys/resource.h>

namespace pdrt {

double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  auto s = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return s(u.ru_utime) + s(u.ru_stime);
}

}  // namespace pdrt
