#pragma once
// CLI11 reports unexpected arguments reversed ("16 --sampls") and suggests nothing. This names
// the unknown options in the order typed, each with the nearest valid option of its subcommand.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace pdrt::cli {

// Optimal string alignment distance (edits, with adjacent transpositions counted as one).
int edit_distance(const std::string& a, const std::string& b);

// The nearest of `names` to `typed` when it is close enough to be a typo, else "".
std::string nearest_name(const std::string& typed, const std::vector<std::string>& names);

// One line for a CLI::ExtrasError of `app` parsed from argv: the unknown options in typed order
// ("render: unknown option --sampls (did you mean --samples?)"), or the unexpected positional
// arguments in typed order when every option was known.
std::string describe_unexpected_arguments(const CLI::App& app, int argc, const char* const* argv);

}  // namespace pdrt::cli
