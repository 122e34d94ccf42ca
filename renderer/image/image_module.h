#pragma once
// Loads the image module (renderer/image/, OpenImageIO inside) on first use: once per process,
// thread-safe. Where it looks: $PDRT_IMAGE_MODULE, then beside the running executable, then
// where the build put it (so tests and benches in other build folders find it).
#include "renderer/image/image_module_abi.h"

#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

// Throws InputError naming the module's path and dlerror() when it cannot be loaded.
const PdrtImageModule& image_module();

struct LinearRgbImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // width * height linear RGB, top row first
};

// An image as linear RGB: 8- and 16-bit integer files are sRGB-decoded; one channel is grey,
// two are grey and alpha, three or more give R, G, B. With max_texels > 0 a larger image is
// refused before its pixels are read. False with a one-line reason (without the path), also
// when the module cannot be loaded.
bool read_linear_rgb(const std::filesystem::path& path, long long max_texels, LinearRgbImage* out, std::string* reason);

}  // namespace pdrt
