// `pdrt collect DIR`: the report of a comparison plan whose jobs have all finished, the same
// report `pdrt compare` writes (its numbers byte for byte), written into DIR.
#include "app/commands.h"
#include "app/compare_request.h"
#include "app/python_plots.h"
#include "renderer/compare/compare_plan.h"
#include "renderer/image/image_output.h"
#include "sampling/core/errors.h"
#include "sampling/core/install_paths.h"

#include <cstdio>
#include <memory>

namespace pdrt::cli {

void add_collect_command(CLI::App& app) {
  struct Opts {
    std::string dir;
    bool quiet = false, no_plots = false;
  };
  auto o = std::make_shared<Opts>();
  auto* cmd = app.add_subcommand("collect", "Write the report of a comparison plan once every job has finished.");
  cmd->add_option("dir", o->dir, "The plan's directory")->required();
  cmd->add_flag("--no-plots", o->no_plots, "Skip the matplotlib plots and index.html");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress on stderr");
  cmd->callback([o] {
    const ComparePlan plan = read_compare_plan(o->dir);
    const std::vector<int> left = unfinished_jobs(plan);
    if (!left.empty()) {
      std::string list;
      for (std::size_t i = 0; i < left.size() && i < 10; ++i) list += (i ? " " : "") + std::to_string(left[i]);
      if (left.size() > 10) list += " ...";
      throw InputError(o->dir + ": " + std::to_string(left.size()) + " of " + std::to_string(plan.jobs.size()) +
                       " jobs have not finished (" + list + "); run them with `" + command_name() + " run-job " +
                       o->dir + " INDEX`");
    }
    CompareRequest r = plan_request(plan);
    r.quiet = o->quiet;
    std::string python;
    if (!o->no_plots) python = find_plot_python();
    PreparedCompare p = prepare_compare(r, false);
    check_plan_scene(plan, p.options);
    p.options.out = o->dir;
    require_image_io();
    const std::filesystem::path results =
        write_compare_report(p.scene, p.options, [&](const CompareJob& job) { return read_plan_job(plan, job); });
    if (!o->no_plots) write_compare_plots(python, p.options.out);
    if (!o->quiet)
      std::fprintf(stderr, "pdrt collect: wrote %s and %s\n", results.c_str(),
                   o->no_plots ? "no plots" : (p.options.out / "index.html").c_str());
  });
}

}  // namespace pdrt::cli
