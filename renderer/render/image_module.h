#pragma once
// Loads the image module (renderer/image/, OpenImageIO inside) on first use: once per process,
// thread-safe. Where it looks: $PDRT_IMAGE_MODULE, then beside the running executable, then
// where the build put it (so tests and benches in other build folders find it).
#include "renderer/image/image_module_abi.h"

namespace pdrt {

// Throws InputError naming the module's path and dlerror() when it cannot be loaded.
const PdrtImageModule& image_module();

}  // namespace pdrt
