// `pdrt sample`: generate a point set with any method and write it as CSV.
#include "sampling/core/atomic_file.h"
#include "app/commands.h"
#include "app/numeric_option.h"
#include "app/output_path.h"
#include "sampling/core/errors.h"
#include "sampling/generators/generator.h"
#include "sampling/core/point_csv.h"

#include <chrono>
#include <cstdio>
#include <memory>

namespace pdrt::cli {

void add_sample_command(CLI::App& app) {
  struct Opts {
    GeneratorParams p;
    std::string out;
    bool quiet = false;
  };
  auto o = std::make_shared<Opts>();
  std::string methods_list;
  for (const auto& m : methods()) methods_list += "\n  " + m.name + ": " + m.summary;
  auto* cmd =
      app.add_subcommand("sample", "Generate a point set in [0,1)^dim and write it as CSV (x0,x1,...[,radius]).");
  cmd->add_option("--method,-m", o->p.method, "Generator:" + methods_list)->required();
  add_integer_option(cmd, "--dim,-d", o->p.dim, IntRange{1, kMaxDim}, "Dimension (gamito 1..5)")->default_str("2");
  auto* count = add_integer_option(cmd, "--count,-n", o->p.count, IntRange{1, INT64_MAX},
                                   "Number of points (exact for random/mccool/lloyd/best-candidate)");
  auto* radius = add_real_option(cmd, "--radius,-r", o->p.radius, "Minimum distance between points");
  count->excludes(radius);
  cmd->add_flag("--periodic", o->p.periodic, "Toroidal domain (distances wrap around)");
  add_integer_option(cmd, "--seed,-s", o->p.seed, IntRange{0, UINT64_MAX}, "Random seed")->default_str("1");
  add_integer_option(
      cmd, "--attempts,-k", o->p.attempts, IntRange{1, INT64_MAX},
      "dart: consecutive failures before stopping (1000); bridson: candidates per active point (30); "
      "mccool: consecutive missed darts before the radius shrinks (30, plus magnification per placed point); "
      "best-candidate: candidates per placed point "
      "(1); lloyd: Monte Carlo probes per point (64); balanced: darts per point (32); stratified-bc: candidates per "
      "point (16); stratified-pd: open intervals tried per point (64)");
  add_real_option(cmd, "--decay", o->p.decay, "mccool: radius multiplier per relaxation step, in (0,1) (0.97)");
  add_real_option(cmd, "--magnification", o->p.magnification,
                  "mccool: extra consecutive misses allowed per placed point (128)");
  add_real_option(cmd, "--start-radius", o->p.start_radius, "mccool: initial radius");
  add_integer_option(cmd, "--iterations", o->p.lloyd_iterations, kLloydIterationsRange, "lloyd: relaxation iterations")
      ->default_str("10");
  cmd->add_option("--out,-o", o->out, "Output CSV file")->required();
  cmd->add_flag("--quiet,-q", o->quiet, "No progress or summary on stderr");
  cmd->callback([o] {
    require_output_path("-o/--out", o->out);
    o->p.quiet = o->quiet;
    validate(o->p);
    check_writable(o->out);
    auto t0 = std::chrono::steady_clock::now();
    PointSet ps = generate(o->p);
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_point_csv(o->out, ps);
    if (!o->quiet)
      std::fprintf(stderr, "pdrt sample: %s placed %zu points in %.3f s -> %s\n", o->p.method.c_str(), ps.size(), secs,
                   o->out.c_str());
  });
}

}  // namespace pdrt::cli
