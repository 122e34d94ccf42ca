#pragma once
// The files a scene load reads (the scene file, included pbrt files, OBJ/MTL and PLY meshes,
// environment images), in the order read. compare's reference cache key hashes their content,
// so that editing any of them cannot reuse a reference cached for the old scene (issue 29).
// Image textures are read at render time; SceneDesc::textures names them.
#include <filesystem>
#include <string>
#include <vector>

namespace pdrt {

// While one is alive on this thread, every file the loaders read is noted in it.
class InputFileRecord {
 public:
  InputFileRecord();
  ~InputFileRecord();
  InputFileRecord(const InputFileRecord&) = delete;
  InputFileRecord& operator=(const InputFileRecord&) = delete;
  const std::vector<std::filesystem::path>& files() const { return files_; }
  // The bytes of the first file read whole as text: the scene file (JSON or the top pbrt file),
  // so that compare keys its cache by them without reading the file again.
  const std::string& first_text() const { return first_text_; }

 private:
  friend void note_input_file(const std::filesystem::path& file);
  // Called by read_text_file with the bytes of the file it noted.
  void note_input_text(const std::string& text);
  friend void note_input_text(const std::string& text);
  std::vector<std::filesystem::path> files_;
  std::string first_text_;
  bool has_text_ = false;
  InputFileRecord* outer_;
};

// Called by the loaders for each file they read; does nothing when no record is alive.
void note_input_file(const std::filesystem::path& file);
// Called by read_text_file with the bytes of the file it noted.
void note_input_text(const std::string& text);

}  // namespace pdrt
