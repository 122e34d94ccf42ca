#include "app/python_plots.h"

#include "sampling/core/install_paths.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

extern char** environ;

namespace pdrt::cli {

// Runs argv with stdout and stderr sent to `log` (or /dev/null); returns the exit status,
// or -1 when the program could not be started.
int run_program(const std::vector<std::string>& argv, const std::string& log) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string plot_script(const std::string& source_relative) {
  const std::filesystem::path name = std::filesystem::path(source_relative).filename();
  if (auto installed = installed_path(std::filesystem::path("share/pdrt/scripts") / name)) return installed->string();
  return std::string(PDRT_SOURCE_DIR) + "/" + source_relative;
}

// The first interpreter that imports matplotlib: $PDRT_PYTHON if set, else python3 on PATH,
// else the system one (a PATH python3 from a version manager may lack Debian's matplotlib).
std::string find_plot_python() {
  std::vector<std::string> candidates;
  if (const char* env = std::getenv("PDRT_PYTHON"); env && *env)
    candidates.push_back(env);
  else
    candidates = {"python3", "/usr/bin/python3"};
  for (const auto& py : candidates)
    if (run_program({py, "-c", "import matplotlib, numpy"}) == 0) return py;
  std::string tried;
  for (const auto& c : candidates) tried += (tried.empty() ? "" : ", ") + c;
  throw std::runtime_error("plots need python3 with matplotlib and numpy (tried " + tried +
                           "; install python3-matplotlib, set PDRT_PYTHON, or pass --no-plots)");
}

}  // namespace pdrt::cli
