// Gamito–Maddock maximal sampling speed, count mode, non-periodic. Targets (single core,
// Release): 2-D 10^5 points <= 0.2 s and 10^6 points <= 2 s.
#include "sampling/generators/generator.h"

#include <benchmark/benchmark.h>

namespace {

void BM_Gamito(benchmark::State& state) {
  pdrt::GeneratorParams p;
  p.method = "gamito";
  p.dim = int(state.range(0));
  p.count = state.range(1);
  int64_t points = 0;
  for (auto _ : state) {
    pdrt::PointSet ps = pdrt::generate(p);
    points += int64_t(ps.size());
    benchmark::DoNotOptimize(ps.coords.data());
    ++p.seed;
  }
  state.SetItemsProcessed(points);
  state.counters["points"] = benchmark::Counter(double(points) / double(state.iterations()));
}

BENCHMARK(BM_Gamito)->ArgNames({"dim", "count"})->Args({2, 100000})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Gamito)->ArgNames({"dim", "count"})->Args({2, 1000000})->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Gamito)->ArgNames({"dim", "count"})->Args({3, 100000})->Unit(benchmark::kMillisecond)->Iterations(2);
// 4-D places ~5k points/s (~3 KB per point at its peak), so fewer points here.
BENCHMARK(BM_Gamito)->ArgNames({"dim", "count"})->Args({4, 20000})->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
