#pragma once
// Progress with an ETA on stderr for long work: one line rewritten in place, at most ten
// times a second, and silent when stderr is not a terminal or the user asked for --quiet.
// The ETA is the measured rate's; with expect(), the expected time's until `trusted` work is
// done (a render's first pass covers the frame, its first tiles only a strip of it).
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace pdrt {

class Progress {
 public:
  Progress(std::string label, double total, bool quiet)
      : label_(std::move(label)), total_(total), enabled_(!quiet && ::isatty(2)), start_(clock::now()) {}
  ~Progress() {
    if (enabled_ && shown_) std::fprintf(stderr, "\r\033[K");
  }

  // Clears the progress line so other output can be printed (the bar reappears on advance).
  void clear_line() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (enabled_ && shown_) std::fprintf(stderr, "\r\033[K");
  }

  void relabel(std::string label) {
    std::lock_guard<std::mutex> lock(mutex_);
    label_ = std::move(label);
  }

  // The whole work is expected to take `seconds`; the ETA says so until `trusted` work is done.
  void expect(double seconds, double trusted) {
    std::lock_guard<std::mutex> lock(mutex_);
    expected_ = seconds, trusted_ = trusted;
  }

  // Thread-safe: adds `amount` of work done.
  void advance(double amount = 1.0) {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    done_ += amount;
    auto now = clock::now();
    if (shown_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    shown_ = true;
    double secs = std::chrono::duration<double>(now - start_).count();
    double frac = total_ > 0 ? done_ / total_ : 1.0;
    double eta = done_ < trusted_ ? expected_ * (1.0 - frac) : frac > 0 ? secs * (1.0 - frac) / frac : 0.0;
    std::fprintf(stderr, "\r\033[K%s: %3.0f%%, %.1f s elapsed, ETA %.1f s", label_.c_str(), 100.0 * frac, secs, eta);
    std::fflush(stderr);
  }

 private:
  using clock = std::chrono::steady_clock;
  std::string label_;
  double total_, done_ = 0.0, expected_ = 0.0, trusted_ = 0.0;
  bool enabled_, shown_ = false;
  clock::time_point start_, last_;
  std::mutex mutex_;
};

}  // namespace pdrt
