#pragma once
// Cache files that pdrt can regenerate (the image-plane pattern, screen-space key tiles): an
// 8-byte magic, the body, then FNV-1a of the body. A file with another magic, size or checksum
// reads as absent, so a damaged cache is regenerated, never trusted.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace pdrt {

// Written all-or-nothing (atomic_file.h); throws InputError when it cannot be written.
void write_checksummed_file(const std::filesystem::path& path, std::string_view magic, std::string_view body);

// The body, when the file exists, starts with `magic`, holds exactly `body_size` bytes after it
// and its checksum matches; otherwise nothing.
std::optional<std::string> read_checksummed_file(const std::filesystem::path& path, std::string_view magic,
                                                 std::size_t body_size);

}  // namespace pdrt
