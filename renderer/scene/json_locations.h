#pragma once
// Source positions for JSON values. nlohmann::json 3.11 keeps no positions, so error
// messages find them by re-scanning the text (already accepted by nlohmann) for a value's
// path. Scanning happens only when a message needs a position, so loading a large inline
// mesh costs no per-value bookkeeping.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace pdrt {

struct JsonLocation {
  int line = 1, col = 1;      // 1-based; columns count UTF-8 characters
  size_t begin = 0, end = 0;  // byte range of a scalar's source text (end == begin for containers)
};

// Paths as messages print them: camera.position, objects[2].radius, materials["my mat"].
std::string json_key_path(const std::string& parent, const std::string& key);
std::string json_index_path(const std::string& parent, size_t index);

class JsonLocations {
 public:
  explicit JsonLocations(std::string_view text) : text_(text) {}

  std::optional<JsonLocation> value(std::string_view path) const;  // the value at `path`
  std::optional<JsonLocation> key(std::string_view path) const;    // the key naming `path`
  // nlohmann silently keeps the last of duplicated keys; the loader rejects them.
  std::optional<std::pair<std::string, JsonLocation>> first_duplicate_key() const;

  // nlohmann refuses numbers beyond double range (1e999) without a position; this finds the first.
  std::optional<std::pair<std::string, JsonLocation>> first_overflowing_number() const;

  // The first '[' or '{' outside strings that opens a container nested more than `limit` deep
  // (a top-level container is depth 1). Works on any text, valid JSON or not, without recursion.
  std::optional<JsonLocation> first_nesting_beyond(size_t limit) const;

  JsonLocation at_byte(size_t offset) const;  // line:col of a byte offset (clamped)
  std::string_view source(const JsonLocation& at) const { return text_.substr(at.begin, at.end - at.begin); }

 private:
  std::optional<JsonLocation> find(std::string_view path, bool want_key) const;
  std::string_view text_;
};

}  // namespace pdrt
