#include "renderer/scene/json_locations.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>
#include <vector>

namespace pdrt {

namespace {

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

struct Frame {
  bool object = false;
  size_t index = 0;            // arrays: the element being read
  std::string key;             // objects: the member being read
  std::set<std::string> seen;  // objects: keys so far (duplicate detection)
};

bool is_number_start(char c) { return c == '-' || (c >= '0' && c <= '9'); }

std::string path_of(const std::vector<Frame>& frames) {
  std::string p;
  for (const Frame& f : frames) p = f.object ? json_key_path(p, f.key) : json_index_path(p, f.index);
  return p;
}

enum class Event { Key, Value };

// Walks text that nlohmann already accepted, so it can skip rather than check syntax.
// Iterative (explicit stack) so deep nesting cannot overflow the call stack.
// visit(event, frames, begin, end) returns true to stop the walk; it may update frames' `seen`.
template <class Visit>
void walk(std::string_view t, Visit&& visit) {
  size_t i = 0, n = t.size();
  auto skip_ws = [&] {
    while (i < n && (t[i] == ' ' || t[i] == '\t' || t[i] == '\n' || t[i] == '\r')) ++i;
  };
  auto skip_string = [&] {  // at the opening quote
    for (++i; i < n && t[i] != '"'; ++i)
      if (t[i] == '\\') ++i;
    ++i;
  };
  if (n >= 3 && t.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // UTF-8 byte order mark
  std::vector<Frame> frames;
  enum class State { Value, Key, After } state = State::Value;
  while (true) {
    skip_ws();
    if (i >= n) return;
    if (state == State::Value) {
      size_t begin = i;
      char c = t[i];
      if (c == '{' || c == '[') {
        if (visit(Event::Value, frames, begin, begin)) return;
        ++i;
        skip_ws();
        if (i < n && (t[i] == '}' || t[i] == ']')) {
          ++i;
          state = State::After;
        } else {
          frames.push_back({});
          frames.back().object = c == '{';
          state = c == '{' ? State::Key : State::Value;
        }
        continue;
      }
      if (c == '"') {
        skip_string();
      } else {
        while (i < n && t[i] != ',' && t[i] != ']' && t[i] != '}' && t[i] != ' ' && t[i] != '\t' && t[i] != '\n' &&
               t[i] != '\r')
          ++i;
      }
      if (visit(Event::Value, frames, begin, i)) return;
      state = State::After;
    } else if (state == State::Key) {
      Frame& f = frames.back();
      size_t begin = i;
      skip_string();
      std::string_view raw = t.substr(begin, i - begin);
      // Escapes are rare in keys; let nlohmann decode them exactly as it did for the value.
      f.key = raw.find('\\') == std::string_view::npos ? std::string(raw.substr(1, raw.size() - 2))
                                                       : nlohmann::json::parse(raw).get<std::string>();
      if (visit(Event::Key, frames, begin, i)) return;
      skip_ws();
      ++i;  // ':'
      state = State::Value;
    } else {  // after a value: ',' or the end of the enclosing container
      if (frames.empty()) return;
      char c = t[i++];
      if (c == ',') {
        if (frames.back().object) {
          state = State::Key;
        } else {
          ++frames.back().index;
          state = State::Value;
        }
      } else {
        frames.pop_back();
      }
    }
  }
}

}  // namespace

std::string json_key_path(const std::string& parent, const std::string& key) {
  if (!is_identifier(key)) return parent + "[" + nlohmann::json(key).dump() + "]";
  return parent.empty() ? key : parent + "." + key;
}

std::string json_index_path(const std::string& parent, size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::optional<JsonLocation> JsonLocations::find(std::string_view path, bool want_key) const {
  std::optional<JsonLocation> found;
  walk(text_, [&](Event e, std::vector<Frame>& frames, size_t begin, size_t end) {
    if ((e == Event::Key) != want_key || path_of(frames) != path) return false;
    found = at_byte(begin);
    found->end = end;
    return true;
  });
  return found;
}

std::optional<JsonLocation> JsonLocations::value(std::string_view path) const { return find(path, false); }
std::optional<JsonLocation> JsonLocations::key(std::string_view path) const { return find(path, true); }

std::optional<std::pair<std::string, JsonLocation>> JsonLocations::first_duplicate_key() const {
  std::optional<std::pair<std::string, JsonLocation>> found;
  walk(text_, [&](Event e, std::vector<Frame>& frames, size_t begin, size_t) {
    if (e != Event::Key || frames.back().seen.insert(frames.back().key).second) return false;
    found.emplace(path_of(frames), at_byte(begin));
    return true;
  });
  return found;
}

std::optional<std::pair<std::string, JsonLocation>> JsonLocations::first_overflowing_number() const {
  std::optional<std::pair<std::string, JsonLocation>> found;
  // The text after the bad number was never checked, but the walk stops at that number.
  walk(text_, [&](Event e, std::vector<Frame>& frames, size_t begin, size_t end) {
    if (e != Event::Value || end == begin || !(is_number_start(text_[begin]))) return false;
    std::string number(text_.substr(begin, end - begin));
    if (std::isfinite(std::strtod(number.c_str(), nullptr))) return false;
    found.emplace(path_of(frames), at_byte(begin));
    found->second.end = end;
    return true;
  });
  return found;
}

std::optional<JsonLocation> JsonLocations::first_nesting_beyond(size_t limit) const {
  size_t depth = 0;
  for (size_t i = 0; i < text_.size(); ++i) {
    char c = text_[i];
    if (c == '"') {
      for (++i; i < text_.size() && text_[i] != '"'; ++i)
        if (text_[i] == '\\') ++i;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return at_byte(i);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return std::nullopt;
}

JsonLocation JsonLocations::at_byte(size_t offset) const {
  offset = std::min(offset, text_.size());
  JsonLocation at;
  at.begin = at.end = offset;
  size_t line_start = text_.size() >= 3 && text_.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  for (size_t i = line_start; i < offset; ++i)
    if (text_[i] == '\n') ++at.line, line_start = i + 1;
  for (size_t i = line_start; i < offset; ++i)
    if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++at.col;  // skip UTF-8 continuation bytes
  return at;
}

}  // namespace pdrt
