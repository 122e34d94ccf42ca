#pragma once
// A child process whose stderr is a terminal (the slave end of a pseudo-terminal), so that
// pdrt shows its progress line as it does for a user; the test reads the master end. The
// progress line appears once the first tile is done: an event a test can wait for where a
// CPU-time budget could still find pdrt starting up on a loaded machine.
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>

namespace pdrt::test {

class TerminalChild {
 public:
  // Runs `sh -c command` with stderr on a new pseudo-terminal; pid() is -1 when that failed.
  explicit TerminalChild(const std::string& command) {
    int slave = -1;
    if (::openpty(&master_, &slave, nullptr, nullptr, nullptr) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(slave, 2);
      ::close(slave);
      ::close(master_);
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(slave);
  }
  ~TerminalChild() {
    if (pid_ > 0 && !reaped_) ::kill(pid_, SIGKILL), wait();
    if (master_ >= 0) ::close(master_);
  }
  TerminalChild(const TerminalChild&) = delete;
  TerminalChild& operator=(const TerminalChild&) = delete;

  pid_t pid() const { return pid_; }
  // Everything the child wrote to stderr so far (with the terminal's \r\n line ends).
  const std::string& text() const { return text_; }

  // Reads until text() holds `needle` (true), or the child closes its stderr or `timeout_s`
  // of wall time pass (false).
  bool read_until(const std::string& needle, double timeout_s) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (text_.find(needle) == std::string::npos) {
      if (std::chrono::steady_clock::now() > end || !read_some(50)) return false;
    }
    return true;
  }

  // Reads until the child closes its stderr, then reaps it; its wait status. Killed first when
  // that takes longer than `timeout_s`.
  int finish(double timeout_s) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    bool open = true;
    while (open && std::chrono::steady_clock::now() < end) open = read_some(50);
    if (open) ::kill(pid_, SIGKILL);
    return wait();
  }

 private:
  // One poll of up to `ms` and what it brought; false once the slave end is closed (EIO/EOF).
  bool read_some(int ms) {
    pollfd p{master_, POLLIN, 0};
    if (::poll(&p, 1, ms) <= 0) return true;
    char buf[4096];
    const ssize_t n = ::read(master_, buf, sizeof buf);
    if (n <= 0) return false;
    text_.append(buf, std::size_t(n));
    return true;
  }
  int wait() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    reaped_ = true;
    return status;
  }

  pid_t pid_ = -1;
  int master_ = -1;
  bool reaped_ = false;
  std::string text_;
};

}  // namespace pdrt::test
