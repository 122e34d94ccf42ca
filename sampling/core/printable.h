#pragma once
// User text (file names, JSON strings, arguments, parser excerpts) quoted in a message is
// made safe for a terminal: control bytes and bytes that are not valid UTF-8 become \xNN, so
// a binary file or a hostile name cannot move the cursor or garble the line. Valid UTF-8 is
// kept as is. Idempotent, so a message may pass through it more than once.
#include <string>
#include <string_view>

namespace pdrt {

std::string printable(std::string_view text);

}  // namespace pdrt
