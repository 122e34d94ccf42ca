#include "renderer/scene/pbrt/ply_check.h"

#include "renderer/scene/text_file.h"
#include "sampling/core/errors.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

namespace pdrt {
namespace {

// Bytes of a PLY scalar type, or 0 for an unknown name (PLY 1.0 names and their sized aliases).
int scalar_size(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}

struct Property {
  bool list = false;
  std::string count_type, type;
};
struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> props;
  int line = 0;
};

// Significant digits of a run of digits: leading zeros cannot overflow a reader.
size_t significant_digits(std::string_view d) {
  const size_t first = d.find_first_not_of('0');
  return first == std::string_view::npos ? 0 : d.size() - first;
}

// Why an ASCII body token is not a `type` value as Assimp 5.2 reads it, or "" if it is one.
// Assimp reads a value by its property's type (digits for unsigned types, a sign and digits for
// signed ones, its own float grammar with a 64-bit integer part) and never checks that the whole
// token was used: the rest of a token is read as the line's next value. A coordinate of 20 digits
// overflowed its integer reader, which then left the digits to be read as a list count and
// allocated 20 GB (found with fuzz_ply), so every token must be one Assimp reads whole.
std::string ascii_value_error(const std::string& tok, const std::string& type) {
  const std::string quoted = "\"" + tok + "\"";
  const bool real = type == "float" || type == "double" || type == "float32" || type == "float64";
  const bool is_unsigned = type[0] == 'u';
  std::string_view s = tok;
  size_t i = 0;
  auto digits = [&] {
    const size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return s.substr(from, i - from);
  };
  const bool sign = i < s.size() && (s[i] == '+' || s[i] == '-');
  if (!real) {
    if (sign && !is_unsigned) ++i;
    const std::string_view d = digits();
    if (d.empty() || i != s.size()) return quoted + " is not a " + type + " (an integer)";
    const int bits = 8 * scalar_size(type);
    const double v = std::strtod(tok.c_str(), nullptr);
    const double lo = is_unsigned ? 0 : -std::ldexp(1.0, bits - 1);
    const double hi = is_unsigned ? std::ldexp(1.0, bits) - 1 : std::ldexp(1.0, bits - 1) - 1;
    if (significant_digits(d) > 10 || v < lo || v > hi)
      return quoted + " is out of range for a " + type + " (" + std::to_string(int64_t(lo)) + " to " +
             std::to_string(int64_t(hi)) + ")";
    return "";
  }
  if (sign) ++i;
  std::string rest(s.substr(i));
  for (char& c : rest) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (rest == "nan" || rest == "inf" || rest == "infinity") return "";
  const std::string not_decimal = quoted + " is not a number (digits, a point, digits, an exponent)";
  const std::string_view whole = digits();
  bool any = !whole.empty();
  if (i < s.size() && s[i] == '.') {
    ++i;
    any = !digits().empty() || any;
  }
  if (!any) return not_decimal;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::string_view exponent = digits();
    if (exponent.empty()) return not_decimal;
    if (significant_digits(exponent) > 19) return quoted + " has an exponent of more than 19 digits";
  }
  if (i != s.size()) return not_decimal;
  if (significant_digits(whole) > 19) return quoted + " has more than 19 digits before its point";
  return "";
}

constexpr size_t kMaxHeader = 1 << 16;  // bytes: a header is a few hundred

// One file's check: the header's elements, then the body against them. `line_no` counts
// the text lines read so far (header, ASCII body).
class PlyChecker {
 public:
  PlyChecker(std::ifstream& in, const std::string& shown) : in_(in), shown_(shown) {}

  void run() {
    header();
    if (format == "ascii") return ascii_body();
    binary_body();
  }

 private:
  [[noreturn]] void fail(int line, int col, const std::string& what) const {
    throw InputError(shown_ + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " + what);
  }

  // Text lines hold no control characters but tabs: Assimp 5.2 crashes, leaks or loops forever
  // on NULs and vertical tabs in a header or an ASCII body, which the checks below would pass
  // (strtod stops at a NUL; >> splits at a vertical tab). Found with tests/fuzz/fuzz_ply.cpp.
  // The header must be ASCII too, as PLY defines it: Assimp 5.2 looped forever on a header whose
  // element name held a byte 0xa0 and whose end_header had no line feed (found with fuzz_ply).
  void refuse_control_characters(const std::string& text, int at_line, const char* part) const {
    const bool ascii = std::string(part) == "header";
    for (size_t i = 0; i < text.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(text[i]);
      if (ascii && c >= 0x80) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", c);
        fail(at_line, int(i + 1), std::string("a byte that is not ASCII (") + hex + ") in the PLY header");
      }
      if ((c < 0x20 && c != '\t') || c == 0x7f) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", c);
        fail(at_line, int(i + 1), std::string("a control character (byte ") + hex + ") in the PLY " + part);
      }
    }
  }

  // A header line's words past its fields: Assimp 5.2 reads some of them (an unknown element's
  // name runs to the line's last space), so they are refused as PLY's grammar has none.
  void refuse_more_words(std::istringstream& words, const std::string& line, const std::string& form) const {
    std::string extra;
    if (!(words >> extra)) return;
    const size_t at = words.tellg() == -1 ? line.size() - extra.size() : size_t(words.tellg()) - extra.size();
    fail(line_no, int(at + 1), "\"" + extra + "\" after the line's fields: " + form);
  }

  // Header: lines up to "end_header".
  void header() {
    size_t header_bytes = 0;
    bool ended = false;
    std::string line;
    while (!ended && std::getline(in_, line)) {
      ++line_no;
      header_bytes += line.size() + 1;
      if (header_bytes > kMaxHeader) fail(line_no, 1, "the PLY header has no end_header in its first 64 KiB");
      if (!line.empty() && line.back() == '\r') line.pop_back();
      refuse_control_characters(line, line_no, "header");
      std::istringstream words(line);
      std::string w;
      words >> w;
      if (line_no == 1) {
        if (w != "ply") fail(1, 1, "not a PLY file (the first line must be \"ply\")");
        continue;
      }
      // Assimp 5.2 reads the format from the second line only, as PLY places it.
      if (line_no == 2 && w != "format") fail(2, 1, "the second line must be \"format <format> 1.0\"");
      if (w.empty() || w == "comment" || w == "obj_info") continue;
      if (w == "format") {
        // Assimp 5.2 takes the first and pdrt took the last: a binary body read as ASCII, or
        // the other way round, crashed Assimp (found checking fuzz_ply's findings).
        if (!format.empty()) fail(line_no, 1, "a second format line");
        std::string version;
        words >> format >> version;
        if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
          fail(line_no, 8, "unknown PLY format \"" + format + "\" (ascii, binary_little_endian, binary_big_endian)");
        if (version != "1.0") fail(line_no, 1, "unsupported PLY version \"" + version + "\" (1.0)");
        refuse_more_words(words, line, "a format line is \"format <format> 1.0\"");
      } else if (w == "element") {
        Element e;
        e.line = line_no;
        std::string count;
        words >> e.name >> count;
        char* end = nullptr;
        e.count = std::strtoull(count.c_str(), &end, 10);
        if (e.name.empty() || count.empty() || *end || count[0] == '-')
          fail(line_no, 1, "an element line is \"element <name> <count>\"");
        refuse_more_words(words, line, "an element line is \"element <name> <count>\"");
        // Assimp 5.2 reads such a name's digits as the element's count (found with fuzz_ply).
        if (std::isdigit(static_cast<unsigned char>(e.name[0])))
          fail(line_no, int(line.find(e.name) + 1),
               "an element name must not start with a digit, got \"" + e.name + "\"");
        elements.push_back(e);
      } else if (w == "property") {
        if (elements.empty()) fail(line_no, 1, "a property before any element");
        Property p;
        std::string t, name;
        words >> t;
        if (t == "list") {
          p.list = true;
          words >> p.count_type >> p.type >> name;
          if (!scalar_size(p.count_type) || p.count_type == "float" || p.count_type == "double" ||
              p.count_type == "float32" || p.count_type == "float64")
            fail(line_no, 15, "a list's count type must be an integer type, got \"" + p.count_type + "\"");
        } else {
          p.type = t;
          words >> name;
        }
        if (!scalar_size(p.type)) fail(line_no, 10, "unknown PLY type \"" + p.type + "\"");
        if (name.empty()) fail(line_no, 1, "a property needs a name");
        refuse_more_words(words, line,
                          p.list ? "a list property is \"property list <count type> <type> <name>\""
                                 : "a property is \"property <type> <name>\"");
        elements.back().props.push_back(p);
      } else if (w == "end_header") {
        // The body starts after its line feed; Assimp 5.2 looped forever without it on the
        // header with a byte 0xa0 above (found with fuzz_ply).
        if (in_.eof()) fail(line_no, int(line.size() + 1), "end_header must end with a line feed");
        ended = true;
      } else {
        fail(line_no, 1, "unknown PLY header keyword \"" + w + "\"");
      }
    }
    if (!ended) fail(line_no, 1, "the PLY header has no end_header");
    if (format.empty()) fail(line_no, 1, "the PLY header has no format line");
    refuse_unskippable_elements();
  }

  // Assimp 5.2 reads the count of vertex, face, tristrips, edge and material elements only; any
  // other element counts 0 there, so the lines of its instances would be read as the next
  // element's (found with fuzz_ply: list counts taken from other lines aborted and allocated
  // 30 GB). Such an element may only come after every element with instances.
  void refuse_unskippable_elements() const {
    for (size_t i = 0; i < elements.size(); ++i) {
      const std::string& n = elements[i].name;
      if (elements[i].count == 0 || n == "vertex" || n == "face" || n == "tristrips" || n == "edge" || n == "material")
        continue;
      for (size_t j = i + 1; j < elements.size(); ++j)
        if (elements[j].count > 0)
          fail(elements[i].line, 1,
               "element \"" + n + "\" has instances before element \"" + elements[j].name +
                   "\", which Assimp 5.2 (pdrt's PLY reader) would misread: only vertex, face, tristrips, edge and "
                   "material elements may come first");
    }
  }

  // One line per element instance; a list's count says how many values follow it.
  void ascii_body() {
    for (const Element& e : elements)
      for (uint64_t i = 0; i < e.count; ++i) {
        std::string body;
        if (!std::getline(in_, body))
          fail(line_no + 1, 1,
               "the body ends at " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count) +
                   " (truncated)");
        ++line_no;
        if (!body.empty() && body.back() == '\r') body.pop_back();
        refuse_control_characters(body, line_no, "body");
        // Assimp 5.2 reads a line of spaces, or the second of two empty lines, as an element and
        // every later line as the one before it (an abort on an empty face; found checking
        // fuzz_ply's findings).
        if (body.find_first_not_of(" \t") == std::string::npos)
          fail(line_no, 1, "a blank line in the PLY body, where every line is one " + e.name);
        std::istringstream v(body);
        size_t col = 0;
        // The next token, which must be one Assimp reads whole as `type` (ascii_value_error).
        auto next = [&](const std::string& type) {
          std::string tok;
          if (!(v >> tok))
            fail(line_no, int(body.size() + 1), e.name + " " + std::to_string(i) + " has too few values");
          col = size_t(v.tellg() == -1 ? body.size() : size_t(v.tellg())) - tok.size() + 1;
          const std::string why = ascii_value_error(tok, type);
          if (!why.empty()) fail(line_no, int(col), why);
          return tok;
        };
        for (const Property& p : e.props) {
          if (!p.list) {
            next(p.type);
            continue;
          }
          const std::string count = next(p.count_type);
          const double n = std::strtod(count.c_str(), nullptr);
          if (n < 0) fail(line_no, int(col), "a list count must be a non-negative integer, got \"" + count + "\"");
          if (n > 1e6) fail(line_no, int(col), "a list of " + std::to_string(uint64_t(n)) + " values");
          // Assimp 5.2 aborts (an assertion) triangulating a face without vertices (found with fuzz_ply).
          if (n == 0 && e.name == "face") fail(line_no, int(col), "face " + std::to_string(i) + " has an empty list");
          for (uint64_t k = 0; k < uint64_t(n); ++k) next(p.type);
        }
        std::string extra;
        if (v >> extra)
          fail(line_no, int(body.size() - extra.size() + 1),
               e.name + " " + std::to_string(i) + " has more values than its properties");
      }
  }

  // Binary: walk the body, reading only the list counts.
  void binary_body() {
    const bool swap = (format == "binary_big_endian") != (std::endian::native == std::endian::big);
    const uint64_t body_start = uint64_t(in_.tellg());
    in_.seekg(0, std::ios::end);
    const uint64_t size = uint64_t(in_.tellg());
    uint64_t pos = body_start;
    auto truncated = [&](const Element& e, uint64_t i) {
      throw InputError(shown_ + ": byte " + std::to_string(size) + ": the body ends inside " + e.name + " " +
                       std::to_string(i) + " of " + std::to_string(e.count) + " (truncated)");
    };
    for (const Element& e : elements) {
      bool fixed = true;
      uint64_t stride = 0;
      for (const Property& p : e.props) {
        if (p.list) fixed = false;
        stride += uint64_t(scalar_size(p.type));
      }
      if (fixed) {
        if (stride && e.count > (size - pos) / stride) truncated(e, (size - pos) / stride);
        pos += stride * e.count;
        continue;
      }
      for (uint64_t i = 0; i < e.count; ++i)
        for (const Property& p : e.props) {
          const int s = scalar_size(p.type);
          if (!p.list) {
            if (pos + uint64_t(s) > size) truncated(e, i);
            pos += uint64_t(s);
            continue;
          }
          const int cs = scalar_size(p.count_type);
          if (pos + uint64_t(cs) > size) truncated(e, i);
          unsigned char b[8] = {};
          in_.seekg(std::streamoff(pos));
          in_.read(reinterpret_cast<char*>(b), cs);
          if (swap) std::reverse(b, b + cs);
          uint64_t n = 0;
          std::memcpy(&n, b, size_t(cs));  // little-endian host: low bytes first
          if ((p.count_type[0] != 'u') && cs < 8 && (b[cs - 1] & 0x80))
            throw InputError(shown_ + ": byte " + std::to_string(pos) + ": " + e.name + " " + std::to_string(i) +
                             " has a negative list count");
          pos += uint64_t(cs);
          if (n > (size - pos) / uint64_t(s)) truncated(e, i);
          pos += n * uint64_t(s);
        }
    }
    if (pos != size)
      throw InputError(shown_ + ": byte " + std::to_string(pos) + ": " + std::to_string(size - pos) +
                       " bytes after the last element");
  }

  std::ifstream& in_;
  const std::string& shown_;
  std::vector<Element> elements;
  std::string format;
  int line_no = 0;
};

}  // namespace

void check_ply(const std::filesystem::path& file, const std::string& shown) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::string reason;
    can_open_file(file, reason);
    throw InputError(shown + ": cannot open: " + reason);
  }
  PlyChecker(in, shown).run();
}

}  // namespace pdrt
