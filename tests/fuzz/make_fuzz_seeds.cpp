// Writes the generated seeds of the table and point-CSV fuzzers: small tables of every family
// and construction (the real ones are hundreds of kilobytes, slow to mutate) and point CSVs of
// a few dimensions, with and without radii, through pdrt's own writers.
// Usage: make_fuzz_seeds TABLE_DIR CSV_DIR
#include "sampling/core/point_csv.h"
#include "sampling/generators/generator.h"
#include "sampling/samplers/sample_table.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_fuzz_seeds TABLE_DIR CSV_DIR\n");
    return 2;
  }
  using namespace pdrt;
  const std::filesystem::path tables = argv[1], csvs = argv[2];
  try {
    std::filesystem::create_directories(tables);
    std::filesystem::create_directories(csvs);
    for (TableSetKind kind : kTableSets)
      for (const TableParams& d : default_table_params(kind)) {
        TableParams p = d;
        p.tables = 2;
        p.points = p.family == Family::Pixel ? 8 : 32;
        p.tile = p.family == Family::Pixel ? 2 : 1;
        write_table(tables / table_file_name(p.family, kind), generate_table(p));
      }
    for (const char* method : {"random", "bridson", "stratified-pd"})
      for (int dim : {1, 2, 3}) {
        GeneratorParams g;
        g.method = method, g.dim = dim, g.count = 12, g.seed = 3;
        try {
          write_point_csv(csvs / (std::string(method) + "-" + std::to_string(dim) + "d.csv"), generate(g));
        } catch (const std::exception&) {
          // This method does not take this dimension or a count; the others cover it.
        }
      }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_fuzz_seeds: %s\n", e.what());
    return 1;
  }
  return 0;
}
