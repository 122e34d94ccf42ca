#pragma once
// Errors a user can cause. The CLI maps UsageError to exit 2 and InputError to exit 1;
// the message is one line that names the argument or file:line.
#include <stdexcept>
#include <string>

namespace pdrt {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The user interrupted (Ctrl-C) after partial output was written: exit 130.
struct InterruptedError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace pdrt
