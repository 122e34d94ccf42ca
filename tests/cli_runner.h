#pragma once
// Runs the pdrt executable for CLI tests and captures its exit code and stderr.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pdrt::test {

struct CliResult {
  int exit_code;
  std::string err;  // stderr
};

inline std::filesystem::path scratch_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("pdrt_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline CliResult run_pdrt(const std::string& args) {
  auto err_file = std::filesystem::temp_directory_path() / ("pdrt_cli_err_" + std::to_string(::getpid()));
  std::string cmd = std::string(PDRT_BINARY) + " " + args + " >/dev/null 2>" + err_file.string();
  int status = std::system(cmd.c_str());
  std::ifstream in(err_file);
  std::stringstream ss;
  ss << in.rdbuf();
  std::filesystem::remove(err_file);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

inline int line_count(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace pdrt::test
