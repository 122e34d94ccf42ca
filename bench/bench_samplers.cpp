// Sampler lookup cost (issue 3 target: <= 10 ns per 2-D poisson sample on one core), both
// random access through Sampler::get_2d and the renderer's sequential PixelSampleState path, and
// default table generation time (<= 10 s on one core).
#include "sampling/samplers/poisson_sampler.h"
#include "sampling/samplers/sample_table.h"
#include "sampling/core/rng.h"

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

// A path tracer's access pattern (issue 15 defect 4): per pixel 64 samples; each takes the
// camera's pixel, time and lens values, then per vertex d < 8 the light pick, light, lobe,
// gloss and roulette values, reaching vertex d with probability 0.8^d (the hash h decides, the
// same for every sampler). Items are values, so ns per value compare across samplers.
// Sample h's values: their sum (so that none is optimised away) and their count.
struct PathValues {
  double sum;
  int count;
};
inline PathValues path_sample(const pdrt::PixelSampleState& ps, uint64_t h) {
  double sum = ps.get_2d(pdrt::Family::Pixel)[0] + ps.get_1d(pdrt::Family::Time, 0) + ps.get_2d(pdrt::Family::Lens)[0];
  int count = 3;
  for (int d = 0; d < 8 && (d == 0 || ((h >> (8 * d)) & 255) < 205); ++d) {  // 205/256 = 0.8
    sum += ps.get_1d(pdrt::Family::Time, 1 + 3 * d) + ps.get_2d(pdrt::Family::Light, d)[0] +
           ps.get_1d(pdrt::Family::Time, 2 + 3 * d) + ps.get_2d(pdrt::Family::Gloss, d)[1] +
           ps.get_1d(pdrt::Family::Time, 3 + 3 * d);
    count += 5;
  }
  return {sum, count};
}

// One pixel's 64 samples in one pass.
void BM_PathPattern(benchmark::State& state, const char* name) {
  auto s = pdrt::make_sampler(name, 1);
  pdrt::PixelSampleState ps(*s);
  int64_t pixel = 0, values = 0;
  double acc = 0;
  for (auto _ : state) {
    const int px = int(pixel & 255), py = int(pixel >> 8) & 255;
    ++pixel;
    ps.set_pixel_pass(0, 64);
    for (int64_t i = 0; i < 64; ++i) {
      ps.start_pixel_sample(px, py, i);
      const PathValues v = path_sample(ps, pdrt::mix64(uint64_t(pixel) * 64 + uint64_t(i)));
      acc += v.sum, values += v.count;
    }
  }
  benchmark::DoNotOptimize(acc);
  state.SetItemsProcessed(values);
}
// The same paths in a progressive render's passes (renderer/render/progressive_passes.h): the
// pixels of a 16 x 16 tile each take samples [0, 4), then [4, 8), [8, 16), ... up to spp (one
// pass [0, spp) below 4), a pass over all of them at a time, so every pass meets every pixel's
// streams afresh.
void tile_in_passes(benchmark::State& state, const char* name, int64_t spp) {
  // Shaped as a render of spp samples makes them: zsobol and poisson-ss take a block of the
  // pixel's samples per pass's spp, and a 16-spp shape would cut 64 spp into four blocks.
  auto s = pdrt::make_sampler(name, 1, {spp, 256, 256});
  pdrt::PixelSampleState ps(*s);
  int64_t tile = 0, values = 0;
  double acc = 0;
  for (auto _ : state) {
    ++tile;
    for (int64_t begin = 0, end = std::min<int64_t>(4, spp); begin < spp; begin = end, end = std::min(2 * end, spp))
      for (int p = 0; p < 256; ++p) {
        const int px = int(tile & 15) * 16 + (p & 15), py = int(tile >> 4 & 15) * 16 + (p >> 4);
        ps.set_pixel_pass(begin, end);
        for (int64_t i = begin; i < end; ++i) {
          ps.start_pixel_sample(px, py, i);
          const PathValues v = path_sample(ps, pdrt::mix64((uint64_t(tile) << 8 | uint64_t(p)) * 64 + uint64_t(i)));
          acc += v.sum, values += v.count;
        }
      }
  }
  benchmark::DoNotOptimize(acc);
  state.SetItemsProcessed(values);
}
// 64 spp.
void BM_PathPatternPasses(benchmark::State& state, const char* name) { tile_in_passes(state, name, 64); }

// The sample counts of compare's sweeps (1, 4 and 16 spp): each pass prepares a pixel's streams
// for a few values, so the per-stream cost of preparing weighs on every value.
void BM_PathPatternFewSamples(benchmark::State& state, const char* name) {
  tile_in_passes(state, name, state.range(0));
}
// The path-pattern benchmarks of every sampler.
#define PDRT_PATH_PATTERNS(id, name)                 \
  BENCHMARK_CAPTURE(BM_PathPattern, id, name);       \
  BENCHMARK_CAPTURE(BM_PathPatternPasses, id, name); \
  BENCHMARK_CAPTURE(BM_PathPatternFewSamples, id, name)->Arg(1)->Arg(4)->Arg(16)
PDRT_PATH_PATTERNS(random, "random");
PDRT_PATH_PATTERNS(jitter, "jitter");
PDRT_PATH_PATTERNS(poisson, "poisson");
PDRT_PATH_PATTERNS(poisson_065, "poisson-065");
PDRT_PATH_PATTERNS(sobol, "sobol");
PDRT_PATH_PATTERNS(pmj02bn, "pmj02bn");
PDRT_PATH_PATTERNS(zsobol, "zsobol");
PDRT_PATH_PATTERNS(poisson_ss, "poisson-ss");
PDRT_PATH_PATTERNS(poisson_bn, "poisson-bn");
PDRT_PATH_PATTERNS(regular, "regular");
#undef PDRT_PATH_PATTERNS

// Issue 16: a table set must generate in <= 10 s on one core; the build generates both.
void BM_DefaultTablesOneCore(benchmark::State& state, pdrt::TableSetKind kind) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  for (auto _ : state)
    for (const auto& p : pdrt::default_table_params(kind))
      benchmark::DoNotOptimize(pdrt::generate_table(p).coords.data());
}
BENCHMARK_CAPTURE(BM_DefaultTablesOneCore, poisson, pdrt::TableSetKind::Poisson)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_DefaultTablesOneCore, poisson_065, pdrt::TableSetKind::Poisson065)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace
