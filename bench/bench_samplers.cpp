// Sampler lookup cost (issue 3 target: <= 10 ns per 2-D poisson sample on one core), both
// random access through Sampler::get_2d and the renderer's sequential PixelSampleState path, and
// default table generation time (<= 10 s on one core).
#include "sampling/samplers/poisson_sampler.h"
#include "sampling/samplers/sample_table.h"

#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

namespace {

void lookups(benchmark::State& state, const pdrt::Sampler& s, pdrt::Family f) {
  int64_t i = 0;
  double acc = 0;
  for (auto _ : state) {
    // Sweep pixels and indices the way a renderer does: a pixel's samples in order.
    pdrt::Vec2 v = s.get_2d(int(i >> 6) & 255, int(i >> 14) & 255, i & 63, f, 0);
    acc += v[0];
    ++i;
  }
  benchmark::DoNotOptimize(acc);
  state.SetItemsProcessed(state.iterations());
}

void BM_PoissonLens(benchmark::State& state) {
  auto s = pdrt::make_poisson_sampler(1, pdrt::default_tables());
  lookups(state, *s, pdrt::Family::Lens);
}
BENCHMARK(BM_PoissonLens);

void BM_PoissonPixel(benchmark::State& state) {
  auto s = pdrt::make_poisson_sampler(1, pdrt::default_tables());
  lookups(state, *s, pdrt::Family::Pixel);
}
BENCHMARK(BM_PoissonPixel);

// The renderer's path: one PixelSampleState per thread; start_pixel_sample then one value per
// family, so a pixel's streams are prepared at its first sample and later samples read the
// table (the first-sample cost is included, amortised over 64 samples per pixel).
void pixel_sample_lookups(benchmark::State& state, const pdrt::Sampler& s, pdrt::Family f) {
  pdrt::PixelSampleState ps(s);
  int64_t i = 0;
  double acc = 0;
  for (auto _ : state) {
    ps.start_pixel_sample(int(i >> 6) & 255, int(i >> 14) & 255, i & 63);
    pdrt::Vec2 v = ps.get_2d(f);
    acc += v[0];
    ++i;
  }
  benchmark::DoNotOptimize(acc);
  state.SetItemsProcessed(state.iterations());
}

void BM_PixelSampleStatePoissonLens(benchmark::State& state) {
  auto s = pdrt::make_poisson_sampler(1, pdrt::default_tables());
  pixel_sample_lookups(state, *s, pdrt::Family::Lens);
}
BENCHMARK(BM_PixelSampleStatePoissonLens);

void BM_PixelSampleStatePoissonPixel(benchmark::State& state) {
  auto s = pdrt::make_poisson_sampler(1, pdrt::default_tables());
  pixel_sample_lookups(state, *s, pdrt::Family::Pixel);
}
BENCHMARK(BM_PixelSampleStatePoissonPixel);

void BM_Sampler(benchmark::State& state, const char* name) {
  auto s = pdrt::make_sampler(name, 1);
  lookups(state, *s, pdrt::Family::Lens);
}
BENCHMARK_CAPTURE(BM_Sampler, random, "random");
BENCHMARK_CAPTURE(BM_Sampler, jitter, "jitter");
BENCHMARK_CAPTURE(BM_Sampler, sobol, "sobol");

void BM_DefaultTablesOneCore(benchmark::State& state) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  for (auto _ : state)
    for (const auto& p : pdrt::default_table_params()) benchmark::DoNotOptimize(pdrt::generate_table(p).coords.data());
}
BENCHMARK(BM_DefaultTablesOneCore)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
