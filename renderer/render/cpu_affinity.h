#pragma once
// The CPUs this process may run on (its affinity mask: taskset, or the binding mpirun gives each
// rank), and the warning when --threads asks for more. TBB sizes its arena from the same mask, so
// threads beyond it would never run: Open MPI binds each rank to one core by default, and a rank
// asked for --threads 8 then runs 1 thread (docs/distributed.md).
#include <string>

namespace pdrt {

// CPUs in this process's affinity mask (sched_getaffinity); the hardware's count where the
// mask cannot be read.
int allowed_cpus();

// The one-line warning for `--threads requested` on a process allowed `allowed` CPUs, naming
// the count and the mpirun options that give a rank its cores; "" when requested is 0 (all)
// or fits.
std::string thread_request_warning(int requested, int allowed);

// Warns (sampling/core/warnings.h) once per process when `requested` exceeds allowed_cpus().
void warn_thread_request(int requested);

}  // namespace pdrt
