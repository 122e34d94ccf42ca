// `pdrt sample`: generate a point set with any method and write it as CSV.
#include "sampling/core/atomic_file.h"
#include "app/commands.h"
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
  auto* cmd = app.add_subcommand("sample", "Generate a point set in [0,1)^dim and write it as CSV (x0,x1,...[,radius]).");
  cmd->add_option("--method,-m", o->p.method, "Generator:" + methods_list)->required();
  cmd->add_option("--dim,-d", o->p.dim, "Dimension (1..8; gamito 1..5)")->default_val(2);
  auto* count = cmd->add_option("--count,-n", o->p.count, "Number of points (exact for random/mccool/lloyd/best-candidate)");
  auto* radius = cmd->add_option("--radius,-r", o->p.radius, "Minimum distance between points");
  count->excludes(radius);
  cmd->add_flag("--periodic", o->p.periodic, "Toroidal domain (distances wrap around)");
  cmd->add_option("--seed,-s", o->p.seed, "Random seed")->default_val(1);
  cmd->add_option("--attempts,-k", o->p.attempts,
                  "dart: consecutive failures before stopping (1000); bridson: candidates per active point (30); "
                  "mccool: consecutive missed darts before the radius shrinks (30, plus magnification per placed point); best-candidate: candidates per placed point "
                  "(1); lloyd: Monte Carlo probes per point (64)");
  cmd->add_option("--decay", o->p.decay, "mccool: radius multiplier per relaxation step, in (0,1) (0.97)");
  cmd->add_option("--magnification", o->p.magnification,
                  "mccool: extra consecutive misses allowed per placed point (128)");
  cmd->add_option("--start-radius", o->p.start_radius, "mccool: initial radius");
  cmd->add_option("--iterations", o->p.lloyd_iterations, "lloyd: relaxation iterations")->default_val(10);
  cmd->add_option("--out,-o", o->out, "Output CSV file")->required();
  cmd->add_flag("--quiet,-q", o->quiet, "No progress or summary on stderr");
  cmd->callback([o] {
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
