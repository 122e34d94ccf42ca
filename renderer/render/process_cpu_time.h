#pragma once
// CPU seconds (user + system, all threads) this process has used: the cost measure of
// compare's equal-time view (RenderStats::cpu_seconds), which wall time on a shared machine is not.
namespace pdrt {

double process_cpu_seconds();

}  // namespace pdrt
