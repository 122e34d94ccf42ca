// `pdrt analyze`: statistics, spectra and plots of one or more point-set CSVs (several files
// are realizations of one process: their periodograms are averaged).
//
// Every input is read and validated, and the plotting interpreter found, before any heavy work
// or output. Outputs are first written to a staging directory inside DIR and renamed into
// place only when all exist (stats.json last), so a failure leaves DIR as it was.
#include "sampling/analysis/analysis_report.h"
#include "sampling/core/atomic_file.h"
#include "app/commands.h"
#include "app/numeric_option.h"
#include "app/output_path.h"
#include "sampling/core/errors.h"
#include "sampling/core/output_directory.h"
#include "sampling/core/point_csv.h"
#include "app/python_plots.h"
#include "sampling/analysis/table_analysis.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>

extern char** environ;

namespace pdrt::cli {
namespace fs = std::filesystem;

namespace {

std::string last_line_of(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

template <class T>
void write_raw(const fs::path& path, const std::vector<T>& values) {
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(T)));
  });
}

// Removes the staging directory however the command ends.
struct StagingDir {
  fs::path path;
  ~StagingDir() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

}  // namespace

void add_analyze_command(CLI::App& app) {
  struct Opts {
    std::vector<std::string> files;
    std::string table;
    bool periodic = false;
    std::optional<int> resolution;
    bool quiet = false;
    bool no_plots = false;
    std::string out;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand(
      "analyze",
      "Analyse point-set CSVs: min distance, relative radius rho (and per prefix), largest empty ball, chi-square "
      "uniformity, periodogram with radial power and anisotropy (McCool & Fiume 1992 §2). Several files are "
      "realizations whose spectra are averaged. Writes DIR/stats.json, DIR/periodogram.f32 and PNG plots.");
  auto* files = cmd->add_option("files", o->files, "Point CSV files (x0,x1,...[,radius]), all of one dim");
  auto* table = cmd->add_option("--table", o->table,
                                "A sample table file (pdrt tables): every table is a realization; adds rho per "
                                "prefix and, for the pixel family, per pixel to stats.json under \"table\"");
  files->excludes(table);
  table->excludes(files);
  cmd->add_flag("--periodic", o->periodic, "Toroidal distances (for sets generated with --periodic)");
  add_integer_option(cmd, "--resolution", o->resolution, IntRange{0, INT32_MAX},
                     "Periodogram grid size R (even; 2-D: 32..4096, 1-D: 64..16777216); default: the smallest power "
                     "of two >= 4 N^(1/d)");
  cmd->add_flag("--quiet,-q", o->quiet, "No summary on stderr");
  cmd->add_flag("--no-plots", o->no_plots, "Skip the PNG plots (no python3/matplotlib needed)");
  cmd->add_option("--out,-o", o->out, "Output directory (created if missing)")->required();
  cmd->callback([o] {
    auto t0 = std::chrono::steady_clock::now();
    require_output_path("-o/--out", o->out);
    // 1. Validate everything before any expensive work or output.
    std::vector<PointSet> sets;
    std::optional<SampleTable> table;
    if (!o->table.empty()) {
      table = read_table(o->table);
      sets = table_point_sets(*table);
      o->periodic = true;  // tables are torus patterns
      o->files.clear();
      for (uint32_t k = 0; k < table->table_count(); ++k) o->files.push_back(o->table + "#" + std::to_string(k));
    } else {
      if (o->files.empty()) throw UsageError("analyze: give point CSV files or --table FILE");
      for (const auto& f : o->files) sets.push_back(read_point_csv(f));
    }
    check_same_dim(sets, o->files);
    AnalysisOptions opts;
    opts.periodic = o->periodic;
    opts.resolution = resolve_resolution(sets, o->resolution);
    std::string python;
    if (!o->no_plots) python = find_plot_python();
    const fs::path out = o->out;
    std::error_code ec;
    if (fs::exists(out, ec) && !fs::is_directory(out, ec)) throw InputError(o->out + ": exists and is not a directory");
    create_output_directory(out);
    check_writable(out / "stats.json");

    // 2. Compute.
    Analysis a = analyze_point_sets(sets, o->files, opts);
    if (table) a.stats["table"] = table_quality(*table, sets);
    const Periodogram& pg = a.periodogram;
    a.stats["spectrum"]["periodogram_file"] = "periodogram.f32";
    a.stats["spectrum"]["periodogram_layout"] =
        "float32 little-endian, centred: R*R values (2-D, row ky+R/2, column kx+R/2) or R values (1-D, kx+R/2), "
        "for frequencies in [-R/2, R/2)";
    std::vector<std::string> plots;
    if (!o->no_plots) {
      plots = {"points.png", "periodogram.png", "radial_power.png", "prefix_rho.png"};
      if (pg.spectral_dim == 2) plots.push_back("anisotropy.png");
    }
    a.stats["plots"] = plots;

    // 3. Stage every output, then move them into place.
    StagingDir staging{out / (".pdrt-analyze.tmp" + std::to_string(::getpid()))};
    fs::remove_all(staging.path, ec);
    fs::create_directory(staging.path, ec);
    if (ec) throw InputError(staging.path.string() + ": cannot create (" + ec.message() + ")");
    std::vector<float> power(pg.power.begin(), pg.power.end());
    write_raw(staging.path / "periodogram.f32", power);
    write_file_atomically(staging.path / "stats.json", [&](std::ostream& s) { s << a.stats.dump(1) << '\n'; });
    if (!o->no_plots) {
      // The first file's points and radii, already validated, for the point plots.
      write_raw(staging.path / "points.f64", sets.front().coords);
      if (sets.front().has_radius()) write_raw(staging.path / "radius.f64", sets.front().radius);
      ::setenv("MPLBACKEND", "Agg", 1);
      const std::string script = plot_script("sampling/analysis/plot_analysis.py");
      int rc = run_program({python, script, staging.path.string()}, (staging.path / "plot.log").string());
      if (rc != 0) {
        std::string why = last_line_of(staging.path / "plot.log");
        throw std::runtime_error("plotting with " + python + " " + script + " failed" +
                                 (why.empty() ? std::string(rc < 0 ? " to start" : "") : ": " + why));
      }
      for (const auto& p : plots)
        if (!fs::exists(staging.path / p)) throw std::runtime_error("plotting did not write " + p);
    }
    std::vector<std::string> finals = plots;
    finals.push_back("periodogram.f32");
    finals.push_back("stats.json");  // last: its presence means the analysis is complete
    for (const auto& f : finals) {
      fs::rename(staging.path / f, out / f, ec);
      if (ec) throw InputError((out / f).string() + ": cannot write (" + ec.message() + ")");
    }

    if (!o->quiet) {
      double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const auto& s = a.stats;
      auto num = [](const nlohmann::json& v) { return v.is_number() ? v.get<double>() : NAN; };
      std::fprintf(
          stderr,
          "pdrt analyze: %zu file(s), %zu points, dim %d: min distance %.6g, rho %.4g, max empty radius %.6g "
          "(%s), chi2 p %.3g; periodogram %d^%d over %d realization(s); %.2f s -> %s\n",
          sets.size(), sets.front().size(), sets.front().dim, num(s["min_distance"]), num(s["relative_radius"]),
          num(s["max_empty_radius"]),
          s["maximal"].is_boolean() ? (s["maximal"].get<bool>() ? "maximal" : "not maximal") : "maximality undefined",
          num(s["chi2_p"]), pg.resolution, pg.spectral_dim, pg.realizations, secs, o->out.c_str());
    }
  });
}

}  // namespace pdrt::cli
