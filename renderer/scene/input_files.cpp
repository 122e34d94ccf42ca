#include "renderer/scene/input_files.h"

#include <algorithm>

namespace pdrt {

namespace {
thread_local InputFileRecord* g_record = nullptr;
}

InputFileRecord::InputFileRecord() : outer_(g_record) { g_record = this; }
InputFileRecord::~InputFileRecord() { g_record = outer_; }

void note_input_file(const std::filesystem::path& file) {
  for (InputFileRecord* r = g_record; r; r = r->outer_)
    if (std::find(r->files_.begin(), r->files_.end(), file) == r->files_.end()) r->files_.push_back(file);
}

void note_input_text(const std::string& text) {
  for (InputFileRecord* r = g_record; r; r = r->outer_)
    if (!r->has_text_) r->first_text_ = text, r->has_text_ = true;
}

}  // namespace pdrt
