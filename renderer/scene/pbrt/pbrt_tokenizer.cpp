#include "renderer/scene/pbrt/pbrt_tokenizer.h"

#include "sampling/core/errors.h"

namespace pdrt {

PbrtTokenizer::PbrtTokenizer(std::string_view text, std::shared_ptr<const std::string> file)
    : text_(text), file_(std::move(file)) {}

void PbrtTokenizer::advance(size_t n) {
  for (size_t i = 0; i < n && pos_ < text_.size(); ++i, ++pos_) {
    if (text_[pos_] == '\n') {
      ++line_, col_ = 1;
    } else {
      ++col_;
    }
  }
}

PbrtToken PbrtTokenizer::next() {
  for (;;) {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r'))
      advance(1);
    if (pos_ < text_.size() && text_[pos_] == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') advance(1);
      continue;
    }
    break;
  }
  PbrtToken t;
  t.at = here();
  if (pos_ >= text_.size()) return t;
  const char c = text_[pos_];
  if (c == '[' || c == ']') {
    t.kind = c == '[' ? PbrtToken::Kind::Open : PbrtToken::Kind::Close;
    t.text = std::string(1, c);
    advance(1);
    return t;
  }
  if (c == '"') {
    t.kind = PbrtToken::Kind::String;
    advance(1);
    for (;;) {
      if (pos_ >= text_.size() || text_[pos_] == '\n')
        throw InputError(t.at.str() + ": string is not closed on its line (missing '\"')");
      char d = text_[pos_];
      if (d == '"') {
        advance(1);
        return t;
      }
      if (d == '\\') {
        const PbrtLocation esc = here();
        advance(1);
        if (pos_ >= text_.size()) throw InputError(esc.str() + ": string ends inside an escape");
        switch (text_[pos_]) {
          case 'b':
            d = '\b';
            break;
          case 'f':
            d = '\f';
            break;
          case 'n':
            d = '\n';
            break;
          case 'r':
            d = '\r';
            break;
          case 't':
            d = '\t';
            break;
          case '\\':
            d = '\\';
            break;
          case '\'':
            d = '\'';
            break;
          case '"':
            d = '"';
            break;
          default:
            throw InputError(esc.str() + ": unknown escape '\\" + std::string(1, text_[pos_]) + "' in a string");
        }
      }
      t.text.push_back(d);
      advance(1);
    }
  }
  if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
    throw InputError(t.at.str() + ": unexpected control character (byte " +
                     std::to_string(int(static_cast<unsigned char>(c))) + ")");
  t.kind = PbrtToken::Kind::Word;
  size_t end = pos_;
  while (end < text_.size()) {
    const char d = text_[end];
    if (d == ' ' || d == '\t' || d == '\n' || d == '\r' || d == '"' || d == '[' || d == ']' || d == '#') break;
    ++end;
  }
  t.text = std::string(text_.substr(pos_, end - pos_));
  advance(end - pos_);
  return t;
}

}  // namespace pdrt
