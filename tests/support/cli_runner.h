#pragma once
// Runs the pdrt executable for CLI tests: exit code and stderr, plus per-process scratch
// directories that are removed when the test program exits.
#include <sys/wait.h>
#include <unistd.h>

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

inline std::filesystem::path scratch_base() {
  std::string name = "pdrt_test_";  // appended, not literal + string: GCC 12 -Wrestrict false positive
  name += std::to_string(::getpid());
  return std::filesystem::temp_directory_path() / name;
}

struct ScratchCleanup {
  ~ScratchCleanup() {
    std::error_code ec;
    std::filesystem::remove_all(scratch_base(), ec);
  }
};
inline ScratchCleanup scratch_cleanup;

inline std::filesystem::path scratch_dir(const std::string& name) {
  auto dir = scratch_base() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// `args` is appended to the command line as is (quote paths with spaces); `env`, when given,
// is a shell prefix of variable assignments (NAME='value' ...).
inline CliResult run_pdrt(const std::string& args, const std::string& env = "") {
  std::filesystem::create_directories(scratch_base());
  auto err_file = scratch_base() / "stderr.txt";
  std::string cmd = env.empty() ? "'" : env + " '";
  cmd += PDRT_BINARY;
  cmd += "' " + args + " >/dev/null 2>'" + err_file.string() + "'";
  int status = std::system(cmd.c_str());
  std::ifstream in(err_file);
  std::stringstream ss;
  ss << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

inline int line_count(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace pdrt::test
