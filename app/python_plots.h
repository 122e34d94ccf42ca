#pragma once
// Running the matplotlib plot scripts: find an interpreter that has matplotlib and numpy,
// and run a program with its output captured in a log file.
#include <string>
#include <vector>

namespace pdrt::cli {

// Runs argv with stdout and stderr sent to `log` (or /dev/null); returns the exit status,
// or -1 when the program could not be started.
int run_program(const std::vector<std::string>& argv, const std::string& log = "/dev/null");

// A plot script given by its path in the source tree: the installed copy (share/pdrt/scripts)
// when pdrt runs from an install, else the source tree's.
std::string plot_script(const std::string& source_relative);

// The first interpreter that imports matplotlib and numpy; throws with advice otherwise.
std::string find_plot_python();

}  // namespace pdrt::cli
