#pragma once
// Writes a file all-or-nothing: content goes to a temporary file beside the target,
// which is renamed over it only when complete. Users never see a half-written file.
// Missing parent directories are created first (`-o out/g.csv` on a fresh clone).
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace pdrt {

// Throws InputError naming `path` if its directory cannot be created or written, or writing fails.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& writer);

// For writers that need a file name (image libraries): `writer` gets the temporary path.
void write_path_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path& tmp)>& writer);

// Fails early (InputError) when `path` could not be created: its nearest existing ancestor
// directory is not a writable directory, or `path` is a directory. Creates nothing.
void check_writable(const std::filesystem::path& path);

}  // namespace pdrt
