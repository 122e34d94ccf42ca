#pragma once
// Where pdrt's own files are. An installed pdrt (`cmake --install build [--prefix P]`) is
// P/bin/pdrt beside P/lib/pdrt (the image module) and P/share/pdrt (tables, assets, plot
// scripts, scenes): it finds them relative to itself, wherever P is. A pdrt run from its build
// tree finds none of those and uses the build paths compiled in.
#include <filesystem>
#include <optional>
#include <string>

namespace pdrt {

// The running executable (/proc/self/exe); empty when it cannot be read.
std::filesystem::path executable_path();

// <the executable's directory>/../<relative> when it exists.
std::optional<std::filesystem::path> installed_path(const std::filesystem::path& relative);

// How to run this pdrt again in a command printed for the user: "pdrt" when PATH finds this
// very executable, else its absolute path.
std::string command_name();

}  // namespace pdrt
