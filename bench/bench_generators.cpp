// Speed of the point-set generators (issue targets: bridson 2-D >= 2 M points/s on one core;
// mccool 2-D 4096 points <= 100 ms; owen-pd 1024 points <= 0.5 s). Run: ./build/bench/bench_generators
#include "sampling/generators/generator.h"

#include <benchmark/benchmark.h>

namespace {

void run(benchmark::State& state, pdrt::GeneratorParams p) {
  std::size_t points = 0;
  for (auto _ : state) {
    pdrt::PointSet ps = pdrt::generate(p);
    points = ps.size();
    benchmark::DoNotOptimize(ps.coords.data());
    ++p.seed;
  }
  state.SetItemsProcessed(int64_t(points) * state.iterations());
  state.counters["points"] = double(points);
}

// Default parameters of `method` but for the point count.
pdrt::GeneratorParams by_count(const char* method, int64_t count) {
  pdrt::GeneratorParams p;
  p.method = method;
  p.count = count;
  return p;
}

void BM_Bridson(benchmark::State& state) {
  pdrt::GeneratorParams p = by_count("bridson", state.range(1));
  p.dim = int(state.range(0));
  run(state, p);
}
BENCHMARK(BM_Bridson)
    ->Args({2, 100000})
    ->Args({2, 1000000})
    ->Args({3, 100000})
    ->Args({4, 100000})
    ->Args({5, 50000})
    ->Unit(benchmark::kMillisecond);

void BM_McCool(benchmark::State& state) {
  pdrt::GeneratorParams p = by_count("mccool", state.range(1));
  p.dim = int(state.range(0));
  p.periodic = state.range(2) != 0;
  run(state, p);
}
BENCHMARK(BM_McCool)
    ->Args({2, 4096, 0})
    ->Args({2, 4096, 1})
    ->Args({2, 65536, 1})
    ->Args({1, 4096, 1})
    ->Unit(benchmark::kMillisecond);

void BM_Dart(benchmark::State& state) { run(state, by_count("dart", state.range(0))); }
BENCHMARK(BM_Dart)->Arg(4096)->Unit(benchmark::kMillisecond);

void BM_BestCandidate(benchmark::State& state) { run(state, by_count("best-candidate", state.range(0))); }
BENCHMARK(BM_BestCandidate)->Arg(1024)->Unit(benchmark::kMillisecond);

// owen-pd: one table of the 64-table set per iteration (target <= 0.5 s per 1024 points).
void BM_OwenPd(benchmark::State& state) {
  pdrt::GeneratorParams p = by_count("owen-pd", state.range(0));
  p.periodic = true;
  run(state, p);
}
BENCHMARK(BM_OwenPd)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);

void BM_Jitter(benchmark::State& state) { run(state, by_count("jitter", state.range(0))); }
BENCHMARK(BM_Jitter)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

}  // namespace
