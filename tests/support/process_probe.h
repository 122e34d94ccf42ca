#pragma once
// What a test can observe of another process through /proc, so that tests which interrupt a
// running pdrt wait for events (a signal handler installed, CPU time spent rendering) instead
// of fixed sleeps that a loaded machine outruns.
#include <sys/types.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace pdrt::test {

// The CPU seconds (user + system) process `pid` has used so far; -1 once it is gone.
inline double cpu_seconds(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  const std::string stat((std::istreambuf_iterator<char>(in)), {});
  const std::size_t paren = stat.rfind(')');  // the command name may hold spaces
  if (paren == std::string::npos || paren + 2 > stat.size()) return -1;
  std::istringstream fields(stat.substr(paren + 2));
  std::string skip;
  for (int i = 3; i < 14; ++i) fields >> skip;  // fields 3..13: state .. cmajflt
  double utime = 0, stime = 0;
  if (!(fields >> utime >> stime)) return -1;
  return (utime + stime) / double(::sysconf(_SC_CLK_TCK));
}

// Whether process `pid` has installed a handler for `signal` (SigCgt in /proc/PID/status).
inline bool catches_signal(pid_t pid, int signal) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (signal - 1)) & 1;
  return false;
}

// Polls `ready` every 50 ms until it holds (true) or `timeout_s` of wall time pass (false).
template <class Pred>
bool wait_until(Pred&& ready, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (!ready()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

// Waits until each of the `n` processes has spent `seconds` more CPU time than when called
// (however loaded the machine, that much work is done); false after `timeout_s` or when one
// is gone.
inline bool wait_for_cpu_seconds(const pid_t* pids, int n, double seconds, double timeout_s = 300) {
  std::vector<double> start(std::size_t(n > 0 ? n : 0));
  for (int i = 0; i < n; ++i)
    if ((start[i] = cpu_seconds(pids[i])) < 0) return false;
  bool gone = false;
  const bool done = wait_until(
      [&] {
        for (int i = 0; i < n; ++i) {
          const double now = cpu_seconds(pids[i]);
          if (now < 0) return gone = true;
          if (now - start[i] < seconds) return false;
        }
        return true;
      },
      timeout_s);
  return done && !gone;
}

}  // namespace pdrt::test
