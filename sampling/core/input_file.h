#pragma once
// Opening a file to read, with the reason when it cannot be: "points.csv: cannot open: No such
// file or directory", "dir: cannot open: Is a directory" (an ifstream opens a directory on
// Linux and then reads nothing, which used to surface as "empty file" or "truncated").
#include <filesystem>
#include <fstream>

namespace pdrt {

// Throws InputError naming the file and the OS reason.
std::ifstream open_for_reading(const std::filesystem::path& file, std::ios::openmode mode = std::ios::binary);

}  // namespace pdrt
