// `pdrt tables`: (re)generate the precomputed hierarchical Poisson-disk tables.
#include "sampling/core/atomic_file.h"
#include "app/commands.h"
#include "app/numeric_option.h"
#include "app/output_path.h"
#include "sampling/core/errors.h"
#include "sampling/core/output_directory.h"
#include "sampling/core/progress.h"
#include "sampling/samplers/sample_table.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace pdrt::cli {

void add_tables_command(CLI::App& app) {
  struct Opts {
    std::string out, set = "all";
    uint64_t seed = 1;
    bool quiet = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd =
      app.add_subcommand("tables", "Generate the precomputed sample tables (one file per family and table set).");
  cmd->add_option("--out,-o", o->out, "Output directory (created if missing)")->required();
  std::vector<std::string> sets;
  for (TableSetKind k : kTableSets) sets.push_back(table_set_name(k));
  cmd->add_option("--set", o->set, "Table set: " + sets[0] + ", " + sets[1] + " or all")
      ->check(CLI::IsMember([&] {
        sets.push_back("all");
        return sets;
      }()))
      ->default_str("all");
  add_integer_option(cmd, "--seed,-s", o->seed, IntRange{0, UINT64_MAX}, "Seed of the table set")->default_str("1");
  cmd->add_flag("--quiet,-q", o->quiet, "No summary on stderr");
  cmd->callback([o] {
    require_output_path("-o/--out", o->out);
    std::filesystem::path dir(o->out);
    std::vector<TableSetKind> kinds;
    for (TableSetKind k : kTableSets)
      if (o->set == "all" || o->set == table_set_name(k)) kinds.push_back(k);
    create_output_directory(dir);
    double total = 0;
    for (TableSetKind k : kinds)
      for (const TableParams& p : default_table_params(k)) {
        check_writable(dir / table_file_name(p.family, k));
        total += p.tables;
      }
    Progress progress("pdrt tables", total, o->quiet);
    for (TableSetKind k : kinds)
      for (TableParams p : default_table_params(k)) {
        p.seed = o->seed;
        auto t0 = std::chrono::steady_clock::now();
        SampleTable t = generate_table(p, &progress);
        write_table(dir / table_file_name(p.family, k), t);
        double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        progress.clear_line();
        if (!o->quiet)
          std::fprintf(
              stderr, "pdrt tables: %-10s %-5s %-13s %u tables x %u points%s, %.2f MiB, %.2f s\n", table_set_name(k),
              family_name(p.family), construction_name(p.construction), t.table_count(), p.points,
              p.family == Family::Pixel && p.tile > 1
                  ? (" per pixel of a " + std::to_string(p.tile) + "x" + std::to_string(p.tile) + " tile").c_str()
                  : "",
              t.memory_bytes() / 1048576.0, secs);
      }
  });
}

}  // namespace pdrt::cli
