#pragma once
// Whole-file reads for the scene and OBJ loaders, reporting why a file cannot be read
// (strerror text) so messages can say "cannot open "x.obj": No such file or directory".
#include <filesystem>
#include <optional>
#include <string>

namespace pdrt {

// The file's bytes, or nullopt with `reason` set.
std::optional<std::string> read_text_file(const std::filesystem::path& file, std::string& reason);

// Whether the file can be opened for reading; sets `reason` when not. Cheap: no read.
bool can_open_file(const std::filesystem::path& file, std::string& reason);

}  // namespace pdrt
