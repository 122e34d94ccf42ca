#include "renderer/scene/environment_image.h"

namespace pdrt {

bool read_environment_image(const std::filesystem::path& path, EnvironmentImage* out, std::string* reason) {
  return read_linear_rgb(path, kMaxEnvironmentTexels, out, reason);
}

}  // namespace pdrt
