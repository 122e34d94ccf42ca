#pragma once
// Output arguments: an empty path (`-o ''`) is a usage error naming the option, not a
// confusing failure to create "".
#include "sampling/core/errors.h"

#include <string>

namespace pdrt::cli {

inline void require_output_path(const std::string& option, const std::string& path) {
  if (path.empty()) throw UsageError(option + ": empty path");
}

}  // namespace pdrt::cli
