#pragma once
// Each `pdrt` subcommand registers itself on the app; its callback runs the command and
// throws UsageError (exit 2) or InputError (exit 1) with a one-line message.
#include <CLI/CLI.hpp>

namespace pdrt::cli {

void add_sample_command(CLI::App& app);
void add_analyze_command(CLI::App& app);
void add_tables_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_run_job_command(CLI::App& app);
void add_collect_command(CLI::App& app);
void add_fireflies_command(CLI::App& app);

}  // namespace pdrt::cli
