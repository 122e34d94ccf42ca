// `pdrt run-job DIR INDEX...`: runs jobs of a comparison plan (`pdrt compare --plan DIR`).
// Under mpirun, `--all` shares the unfinished jobs among the ranks by estimated cost.
#include "app/commands.h"
#include "app/compare_request.h"
#include "app/numeric_option.h"
#include "distributed/mpi_process_group.h"
#include "renderer/compare/compare_plan.h"
#include "renderer/image/image_output.h"
#include "renderer/scene/scene_limits.h"
#include "sampling/core/errors.h"
#include "sampling/core/install_paths.h"
#include "sampling/core/printable.h"

#include <chrono>
#include <cstdio>
#include <memory>

namespace pdrt::cli {

void add_run_job_command(CLI::App& app) {
  struct Opts {
    std::string dir;
    std::vector<long long> indices;
    bool all = false, quiet = false;
    int threads = 0;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("run-job", "Run jobs of a comparison plan (written by `pdrt compare --plan DIR`).");
  cmd->add_option("dir", o->dir, "The plan's directory")->required();
  cmd->add_option("index", o->indices, "Job indices (0-based, as DIR/jobs.txt lists them)");
  cmd->add_flag(
      "--all", o->all,
      "Every unfinished job; under mpirun each rank takes its share (longest first, balanced by estimated cost)");
  add_integer_option(cmd, "--threads,-t", o->threads, kThreadsRange, "Worker threads (0 = all cores)")
      ->default_str("0");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress on stderr");
  cmd->callback([o] {
    if (o->all == !o->indices.empty()) throw UsageError("give job indices or --all, not both or neither");
    const ComparePlan plan = read_compare_plan(o->dir);
    const long long n = static_cast<long long>(plan.jobs.size());
    for (long long i : o->indices)
      if (i < 0 || i >= n)
        throw UsageError("job index " + std::to_string(i) + ": the plan in " + o->dir + " has jobs 0.." +
                         std::to_string(n - 1));
    CompareRequest r = plan_request(plan);
    const bool lead = launcher_rank() == 0;
    r.threads = o->threads;
    std::vector<int> mine;
    if (o->all) {
      const ProcessGroup& group = process_group();
      mine = jobs_for_rank(plan, compare_options(r), group.rank(), group.size());
    } else {
      for (long long i : o->indices) mine.push_back(int(i));
    }
    auto label = [&](int i) { return describe(plan.jobs[std::size_t(i)]); };
    // Finished jobs need no scene: a resumed sweep skips them without loading it.
    std::vector<int> todo;
    for (int i : mine) {
      if (!job_finished(plan, i))
        todo.push_back(i);
      else if (!o->quiet)
        std::fprintf(stderr, "pdrt run-job: job %d (%s) had already finished\n", i, label(i).c_str());
    }
    if (!todo.empty()) {
      PreparedCompare p = prepare_compare(r, false);
      check_plan_scene(plan, p.options);
      require_image_io();
      p.options.quiet = true;  // the job's own progress lines below say enough
      for (int i : todo) {
        const auto t0 = std::chrono::steady_clock::now();
        try {
          run_plan_job(plan, i, p.scene, p.options);
        } catch (const std::exception& e) {
          if (!o->all || process_group().size() == 1) throw;
          // Only this rank knows: say it here, and end the others rather than let them wait.
          std::fprintf(stderr, "pdrt: rank %d: job %d (%s): %s\n", process_group().rank(), i, label(i).c_str(),
                       printable(e.what()).c_str());
          abort_process_group(1);
        }
        if (!o->quiet)
          std::fprintf(stderr, "pdrt run-job: job %d (%s) done in %.2f s\n", i, label(i).c_str(),
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
    }
    if (o->all) {
      // Every rank's jobs are done when the gather returns: rank 0 can say what is left.
      process_group().all_gather({});
      if (lead && !o->quiet) {
        const std::size_t left = unfinished_jobs(plan).size();
        const std::string collect =
            left ? "" : "; write the report with `" + command_name() + " collect " + o->dir + "`";
        std::fprintf(stderr, "pdrt run-job: %zu of %zu jobs finished%s\n", plan.jobs.size() - left, plan.jobs.size(),
                     collect.c_str());
      }
    }
  });
}

}  // namespace pdrt::cli
