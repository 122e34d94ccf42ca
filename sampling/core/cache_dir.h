#pragma once
// Where pdrt keeps what it can regenerate (sample tables, reference images).
#include <filesystem>

namespace pdrt {

// $XDG_CACHE_HOME/pdrt, else ~/.cache/pdrt, else <temp>/pdrt-cache (XDG base directories).
std::filesystem::path cache_dir();

}  // namespace pdrt
