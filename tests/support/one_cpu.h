#pragma once
// Restricts the calling thread (and the processes it starts, which inherit the mask) to one CPU
// of its affinity mask, as taskset -c or mpirun's default binding would; restores the mask
// when it goes out of scope.
#include <sched.h>

namespace pdrt::test {

class OneCpu {
 public:
  OneCpu() {
    ok_ = sched_getaffinity(0, sizeof saved_, &saved_) == 0;
    int first = 0;
    while (ok_ && first < CPU_SETSIZE && !CPU_ISSET(first, &saved_)) ++first;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(first, &one);
    ok_ = ok_ && first < CPU_SETSIZE && sched_setaffinity(0, sizeof one, &one) == 0;
  }
  ~OneCpu() {
    if (ok_) sched_setaffinity(0, sizeof saved_, &saved_);
  }
  OneCpu(const OneCpu&) = delete;
  OneCpu& operator=(const OneCpu&) = delete;
  bool ok() const { return ok_; }  // the mask was read and set

 private:
  cpu_set_t saved_;
  bool ok_ = false;
};

}  // namespace pdrt::test
