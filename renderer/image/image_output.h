#pragma once
// Writes a rendered image through the image module (OpenImageIO, loaded on first use),
// all-or-nothing (temporary file, then rename).
// EXR: linear float RGB plus the AOV channels; TIFF: linear float RGB; PNG/JPEG: sRGB 8-bit.
// Every format carries the render's metadata as string attributes ("pdrt:sampler", ...).
#include "renderer/image/image.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace pdrt {

using Metadata = std::vector<std::pair<std::string, std::string>>;

// Throws UsageError for an extension OIIO/pdrt cannot write (checked before rendering).
void check_image_extension(const std::filesystem::path& path);

// Loads the image module now: a command that will write images fails (InputError naming the
// module and the loader's reason) before rendering rather than after.
void require_image_io();

void write_image(const std::filesystem::path& path, const Image& image, const Metadata& metadata);

// Writes an 8-bit PNG of values already in display space ([0,1], no transfer curve applied):
// heat maps, crops, sample-count maps.
void write_display_png(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgb);

// Writes linear float RGB alone (no AOVs) to an EXR or TIFF: environment images, textures.
void write_linear_rgb(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgb,
                      const Metadata& metadata);

// Reads the RGB channels of an image (linear for EXR/TIFF float, decoded sRGB for 8-bit).
Image read_image_rgb(const std::filesystem::path& path);

// sRGB transfer function of a linear value, clamped to [0, 1].
float linear_to_srgb(float v);

}  // namespace pdrt
