#include "renderer/scene/environment_image.h"

#include "renderer/scene/input_files.h"

namespace pdrt {

bool read_environment_image(const std::filesystem::path& path, EnvironmentImage* out, std::string* reason) {
  note_input_file(path);
  return read_linear_rgb(path, kMaxEnvironmentTexels, out, reason);
}

}  // namespace pdrt
