// pdrt: the command-line front end over the sampling and renderer libraries.
#include "app/commands.h"
#include "app/unknown_options.h"
#include "distributed/mpi_process_group.h"
#include "sampling/core/errors.h"
#include "sampling/core/printable.h"

#include <cstdio>
#include <exception>
#include <string>

namespace {

// Every message quotes user text (paths, arguments, scene strings): one place makes it safe.
int report(const char* what, int code) {
  // Under mpirun every rank meets the same error; rank 0 says it.
  if (pdrt::launcher_rank() == 0) std::fprintf(stderr, "pdrt: %s\n", pdrt::printable(what).c_str());
  return code;
}

// CLI11 answers an unknown first word with "A subcommand is required"; name the word instead.
void check_subcommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  std::string known;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == argv[1]) return;
    known += (known.empty() ? "" : ", ") + sub->get_name();
  }
  throw pdrt::UsageError(std::string("unknown subcommand \"") + argv[1] + "\" (expected " + known + "; see --help)");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pdrt — a distribution ray tracer with hierarchical Poisson-disk sampling"};
  app.set_version_flag("--version", PDRT_VERSION);
  app.require_subcommand(1);
  // One line per error, as for every other pdrt error.
  app.failure_message(
      [](const CLI::App*, const CLI::Error& e) { return "pdrt: " + pdrt::printable(e.what()) + " (see --help)\n"; });
  pdrt::cli::add_sample_command(app);
  pdrt::cli::add_analyze_command(app);
  pdrt::cli::add_tables_command(app);
  pdrt::cli::add_render_command(app);
  pdrt::cli::add_compare_command(app);
  pdrt::cli::add_convert_command(app);
  pdrt::cli::add_run_job_command(app);
  pdrt::cli::add_collect_command(app);
  pdrt::cli::add_fireflies_command(app);
  try {
    check_subcommand(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::ExtrasError&) {
    return report(pdrt::cli::describe_unexpected_arguments(app, argc, argv).c_str(), 2);
  } catch (const CLI::ParseError& e) {
    int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  } catch (const pdrt::UsageError& e) {
    return report(e.what(), 2);
  } catch (const pdrt::InterruptedError& e) {
    return report(e.what(), 130);
  } catch (const pdrt::InputError& e) {
    return report(e.what(), 1);
  } catch (const std::exception& e) {
    return report(e.what(), 1);
  }
  return 0;
}
