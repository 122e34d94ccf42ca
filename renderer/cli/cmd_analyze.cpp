#include "commands.h"
namespace pdrt::cli {
void add_analyze_command(CLI::App& app) { app.add_subcommand("analyze", "Analyse point sets (not implemented yet)"); }
}  // namespace pdrt::cli
