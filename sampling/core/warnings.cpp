#include "sampling/core/warnings.h"

#include <cstdio>
#include <mutex>
#include <set>

namespace pdrt {

namespace {

struct Warnings {
  std::mutex mutex;  // render threads warn too
  bool hold = false;
  std::set<std::string> printed;  // kinds
  std::vector<std::string> held;
};

Warnings& state() {
  static Warnings w;
  return w;
}

void print_once(Warnings& w, const std::string& kind, const std::string& line) {
  if (!w.printed.insert(kind).second) return;
  std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
}

}  // namespace

void warn(const std::string& line, const std::string& kind) {
  Warnings& w = state();
  std::lock_guard<std::mutex> lock(w.mutex);
  const std::string& k = kind.empty() ? line : kind;
  if (w.hold)
    w.held.push_back(k + '\n' + line);
  else {
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
    w.printed.insert(k);
  }
}

void hold_warnings() {
  Warnings& w = state();
  std::lock_guard<std::mutex> lock(w.mutex);
  w.hold = true;
}

std::vector<std::string> take_held_warnings() {
  Warnings& w = state();
  std::lock_guard<std::mutex> lock(w.mutex);
  std::vector<std::string> out;
  out.swap(w.held);
  return out;
}

void print_held_warnings(const std::vector<std::string>& held) {
  Warnings& w = state();
  std::lock_guard<std::mutex> lock(w.mutex);
  for (const std::string& h : held) {
    const std::size_t cut = h.find('\n');
    if (cut == std::string::npos) continue;
    print_once(w, h.substr(0, cut), h.substr(cut + 1));
  }
}

}  // namespace pdrt
