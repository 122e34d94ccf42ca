// Point CSV write time (issue 13 target: 10^6 2-D points with radii in <= 0.3 s), beside the
// former per-value snprintf("%.9g") + ostream `<<` per row writer as the baseline.
#include "sampling/core/atomic_file.h"
#include "sampling/core/point_csv.h"
#include "sampling/core/rng.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace {

pdrt::PointSet points(std::size_t n) {
  pdrt::PointSet ps;
  ps.dim = 2;
  pdrt::Rng rng(1);
  for (std::size_t i = 0; i < n; ++i) {
    ps.coords.push_back(rng.uniform()), ps.coords.push_back(rng.uniform());
    ps.radius.push_back(1e-3 * rng.uniform());
  }
  return ps;
}

std::filesystem::path out_path() { return std::filesystem::temp_directory_path() / "pdrt_bench_points.csv"; }

void BM_WritePointCsv(benchmark::State& state) {
  const pdrt::PointSet ps = points(std::size_t(state.range(0)));
  for (auto _ : state) pdrt::write_point_csv(out_path(), ps);
  state.SetItemsProcessed(state.iterations() * state.range(0));
  std::filesystem::remove(out_path());
}
BENCHMARK(BM_WritePointCsv)->Arg(1000000)->Unit(benchmark::kMillisecond);

// The writer before issue 13, kept only as the measuring stick.
void BM_WritePointCsvSnprintfBaseline(benchmark::State& state) {
  const pdrt::PointSet ps = points(std::size_t(state.range(0)));
  for (auto _ : state)
    pdrt::write_file_atomically(out_path(), [&](std::ostream& out) {
      out << "x0,x1,radius\n";
      char buf[64];
      std::string line;
      for (std::size_t i = 0; i < ps.size(); ++i) {
        line.clear();
        for (int k = 0; k < 2; ++k) {
          std::snprintf(buf, sizeof buf, k ? ",%.9g" : "%.9g", ps.point(i)[k]);
          line += buf;
        }
        std::snprintf(buf, sizeof buf, ",%.9g", ps.radius[i]);
        line += buf;
        line += '\n';
        out << line;
      }
    });
  state.SetItemsProcessed(state.iterations() * state.range(0));
  std::filesystem::remove(out_path());
}
BENCHMARK(BM_WritePointCsvSnprintfBaseline)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace
