#pragma once
// Splits pbrt-v4 scene text into tokens (pbrt-v4's file-format documentation, "Scene file
// format"): bare words (directives, numbers, true/false), quoted strings, '[' and ']'. '#'
// starts a comment that runs to the end of the line. Every token knows its file:line:col, so
// every later message can name where it comes from.
#include <memory>
#include <string>
#include <string_view>

namespace pdrt {

struct PbrtLocation {
  std::shared_ptr<const std::string> file;  // as the user or the Include named it
  int line = 1, col = 1;                    // 1-based; columns count bytes
  std::string str() const {
    return (file ? *file : std::string("<text>")) + ":" + std::to_string(line) + ":" + std::to_string(col);
  }
};

struct PbrtToken {
  enum class Kind { Word, String, Open, Close, End } kind = Kind::End;
  std::string text;  // a word as written; a string without its quotes, escapes resolved
  PbrtLocation at;
};

class PbrtTokenizer {
 public:
  // `text` must outlive the tokenizer. `file` names it in messages.
  PbrtTokenizer(std::string_view text, std::shared_ptr<const std::string> file);

  // The next token (Kind::End at the end of the text). Throws InputError "file:line:col: ..."
  // for a string that is not closed on its line, an unknown escape or a control character.
  PbrtToken next();
  PbrtLocation here() const { return {file_, line_, col_}; }

 private:
  void advance(size_t n);
  std::string_view text_;
  std::shared_ptr<const std::string> file_;
  size_t pos_ = 0;
  int line_ = 1, col_ = 1;
};

}  // namespace pdrt
