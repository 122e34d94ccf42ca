#pragma once
// Checks a PLY file's header and that its body holds exactly what the header declares, before
// Assimp reads it: Debian 12's Assimp 5.2 loops forever on a header without `end_header` and
// silently accepts truncated bodies. Messages name the file and the line:col (header, ASCII
// body) or the byte offset (binary body).
#include <filesystem>
#include <string>

namespace pdrt {

// Throws InputError "<shown>:<line>:<col>: ..." or "<shown>: byte <n>: ..." on the first problem.
void check_ply(const std::filesystem::path& file, const std::string& shown);

}  // namespace pdrt
