#include "sampling/core/text_writer.h"

#include <charconv>

namespace pdrt {

namespace {
// Longest std::to_chars output of a double ("-2.2250738585072014e-308") or an int64, with room.
constexpr std::size_t kMaxNumber = 32;
}  // namespace

TextWriter::TextWriter(std::ostream& out, std::size_t capacity) : out_(out), buf_(capacity < 64 ? 64 : capacity) {}

void TextWriter::put(std::string_view s) {
  if (s.size() > buf_.size()) {
    flush();
    out_.write(s.data(), std::streamsize(s.size()));
    return;
  }
  reserve(s.size());
  s.copy(buf_.data() + size_, s.size());
  size_ += s.size();
}

void TextWriter::number(double v) {
  reserve(kMaxNumber);
  size_ = std::size_t(std::to_chars(buf_.data() + size_, buf_.data() + buf_.size(), v).ptr - buf_.data());
}

void TextWriter::integer(std::int64_t v) {
  reserve(kMaxNumber);
  size_ = std::size_t(std::to_chars(buf_.data() + size_, buf_.data() + buf_.size(), v).ptr - buf_.data());
}

void TextWriter::flush() {
  if (size_ == 0) return;
  out_.write(buf_.data(), std::streamsize(size_));
  size_ = 0;
}

}  // namespace pdrt
