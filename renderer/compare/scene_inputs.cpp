#include "renderer/compare/scene_inputs.h"

#include "sampling/core/hash.h"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace pdrt {

namespace fs = std::filesystem;

namespace {
std::string file_entry(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "|" + string.
  // The name, not the path: a plan made on one machine runs on another with the checkout elsewhere.
  std::string entry = "|";
  entry += file.filename().string();
  if (!in || fs::is_directory(file, ec)) return entry += " unreadable";
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  entry += ' ';
  entry += std::to_string(bytes.size());
  entry += ' ';
  entry += std::to_string(fnv1a(bytes));
  return entry;
}
}  // namespace

std::string scene_inputs_text(const SceneDesc& scene, const std::vector<fs::path>& read) {
  std::vector<fs::path> files;
  for (const fs::path& f : read)
    if (f != scene.file) files.push_back(f);
  for (const TextureDesc& t : scene.textures)
    if (t.kind == TextureDesc::Kind::Image && std::find(files.begin(), files.end(), t.file) == files.end())
      files.push_back(t.file);
  std::string text;
  for (const fs::path& f : files) text += file_entry(f);
  return text;
}

}  // namespace pdrt
