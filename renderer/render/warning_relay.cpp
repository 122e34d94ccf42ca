#include "renderer/render/warning_relay.h"

#include "sampling/core/warnings.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pdrt {

void relay_held_warnings(const ProcessGroup& group) {
  std::vector<std::byte> held;
  for (const std::string& h : take_held_warnings()) {
    const auto* c = reinterpret_cast<const std::byte*>(h.c_str());
    held.insert(held.end(), c, c + h.size() + 1);  // with its '\0'
  }
  const std::vector<std::vector<std::byte>> all = group.all_gather(held);
  if (group.rank() != 0) return;
  for (const std::vector<std::byte>& b : all) {
    std::vector<std::string> lines;
    for (std::size_t at = 0; at < b.size();) {
      lines.emplace_back(reinterpret_cast<const char*>(b.data() + at));
      at += lines.back().size() + 1;
    }
    print_held_warnings(lines);
  }
}

}  // namespace pdrt
