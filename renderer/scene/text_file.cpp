#include "renderer/scene/text_file.h"

#include "renderer/scene/input_files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

namespace pdrt {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// fopen succeeds on a directory on Linux; reject it up front with the errno a read would give.
File open_regular(const std::filesystem::path& file, std::string& reason) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    reason = std::strerror(EISDIR);
    return nullptr;
  }
  errno = 0;
  File f(std::fopen(file.c_str(), "rb"));
  if (!f) reason = std::strerror(errno ? errno : ENOENT);
  return f;
}

}  // namespace

std::optional<std::string> read_text_file(const std::filesystem::path& file, std::string& reason) {
  File f = open_regular(file, reason);
  if (!f) return std::nullopt;
  note_input_file(file);
  std::string text;
  char buf[1 << 16];
  size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f.get())) > 0) text.append(buf, got);
  if (std::ferror(f.get())) {
    reason = std::strerror(errno ? errno : EIO);
    return std::nullopt;
  }
  note_input_text(text);
  return text;
}

bool can_open_file(const std::filesystem::path& file, std::string& reason) {
  return open_regular(file, reason) != nullptr;
}

}  // namespace pdrt
