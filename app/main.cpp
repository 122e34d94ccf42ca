// pdrt: the command-line front end over the sampling and renderer libraries.
#include "app/commands.h"
#include "sampling/core/errors.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  CLI::App app{"pdrt — a distribution ray tracer with hierarchical Poisson-disk sampling"};
  app.set_version_flag("--version", PDRT_VERSION);
  app.require_subcommand(1);
  // One line per error, as for every other pdrt error.
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string("pdrt: ") + e.what() + " (see --help)\n"; });
  pdrt::cli::add_sample_command(app);
  pdrt::cli::add_analyze_command(app);
  pdrt::cli::add_tables_command(app);
  pdrt::cli::add_render_command(app);
  pdrt::cli::add_compare_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  } catch (const pdrt::UsageError& e) {
    std::fprintf(stderr, "pdrt: %s\n", e.what());
    return 2;
  } catch (const pdrt::InterruptedError& e) {
    std::fprintf(stderr, "pdrt: %s\n", e.what());
    return 130;
  } catch (const pdrt::InputError& e) {
    std::fprintf(stderr, "pdrt: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pdrt: %s\n", e.what());
    return 1;
  }
  return 0;
}
