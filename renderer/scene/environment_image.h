#pragma once
// Reading the image of an environment light (docs/scene-format.md, "environment") through
// the image module (OpenImageIO, loaded on first use): linear RGB floats, top row first.
// The channels and the sRGB decoding are read_linear_rgb's (image_module.h), as for every
// image pdrt reads.
// Finding the file: the scene's directory first, then the generated assets (asset_path.h).
#include "renderer/image/image_module.h"

#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

// Images of more texels are refused before their pixels are read (about 200 MB of RGB and
// 130 MB of sampling tables).
inline constexpr long long kMaxEnvironmentTexels = 1ll << 24;

using EnvironmentImage = LinearRgbImage;

// False with a one-line reason (without the path) when the file cannot be read.
bool read_environment_image(const std::filesystem::path& path, EnvironmentImage* out, std::string* reason);

}  // namespace pdrt
