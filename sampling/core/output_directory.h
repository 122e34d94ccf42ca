#pragma once
// Output directories pdrt creates for the user (`-o out/new/x.png` on a fresh clone) are said on
// stderr, so that a mistyped path does not silently leave a new tree behind (issue 29).
#include <filesystem>

namespace pdrt {

// Creates `dir` and its missing ancestors, and notes the topmost one it created ("pdrt: created
// directory 'out'"). Throws InputError naming `dir` and the reason when it cannot.
void create_output_directory(const std::filesystem::path& dir);

}  // namespace pdrt
