#pragma once
// A JSON file parsed strictly, and checked access to its values. Every failure is an
// InputError of one line, "<file>:<line>:<col>: <json.path> <what is wrong>, got <value>",
// so the scene loader states its rules and never formats a position itself.
#include "renderer/scene/json_locations.h"
#include "sampling/core/int_range.h"
#include "sampling/core/name_table.h"
#include "renderer/scene/vec3.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

namespace pdrt {

class JsonNode;

// Containers nested deeper than this are refused before anything recurses over the document
// (a scene needs about 6: objects[i].transform.rotate[j].axis). Messages render values
// recursively, so the cap is what keeps hostile input from overflowing the stack.
inline constexpr size_t kMaxJsonDepth = 64;

class JsonDocument {
 public:
  // Rejects what nlohmann accepts or reports without a position: syntax errors (at the
  // offending character), nesting deeper than kMaxJsonDepth, duplicated keys, numbers beyond
  // double range.
  JsonDocument(std::string name, std::string text);
  JsonDocument(const JsonDocument&) = delete;  // locations_ views text_
  JsonDocument& operator=(const JsonDocument&) = delete;

  const std::string& name() const { return name_; }
  const JsonLocations& locations() const { return locations_; }
  JsonNode root() const;
  std::string position(const std::optional<JsonLocation>& at) const;  // "<file>:<line>:<col>"
  [[noreturn]] void fail(const std::optional<JsonLocation>& at, const std::string& message) const;

 private:
  std::string name_, text_;
  JsonLocations locations_;
  nlohmann::json root_;
};

class JsonObject;

// A value and its path. Accessors check type and range and fail at the value's position.
class JsonNode {
 public:
  JsonNode(const JsonDocument& doc, const nlohmann::json& v, std::string path)
      : doc_(&doc), v_(&v), path_(std::move(path)) {}
  const nlohmann::json& value() const { return *v_; }
  const std::string& path() const { return path_; }
  const JsonDocument& document() const { return *doc_; }

  std::string where() const;                              // "<file>:<line>:<col>: <path>", for messages raised later
  [[noreturn]] void fail(const std::string& what) const;  // "<path> <what>"
  [[noreturn]] void fail_got(const std::string& what) const;  // "<path> <what>, got <value>"
  [[noreturn]] void fail_key(const std::string& what) const;  // at the key naming this value
  // Scalars as written (1e999 stays 1e999); containers abbreviated to a few levels and at
  // most ~60 characters, however large or deep the value.
  std::string shown() const;

  float number() const;  // finite, within float range
  float positive() const;
  float non_negative() const;
  float in_unit_interval() const;
  long long integer(long long lo, long long hi) const;  // written as an integer, in [lo, hi]
  int int_at_least(int lo) const;
  uint64_t integer_in(IntRange range) const;  // written as an integer, in range
  bool boolean() const;
  std::string string() const;
  std::string choice(std::initializer_list<const char*> options) const;
  // The value a name table gives the string ("must be one of a, b, c" otherwise).
  template <class E, std::size_t N>
  E choice(const NamedValue<E> (&table)[N]) const {
    E v{};
    if (!parse_name_in(table, string(), &v)) fail_got("must be one of " + name_list(table));
    return v;
  }
  Vec3 vec3() const;
  Vec3 nonzero_vec3() const;
  Vec3 color() const;                        // reflectance: components in [0, 1]
  Vec3 radiance() const;                     // components >= 0
  size_t array_size(size_t min_size) const;  // must be an array of at least min_size
  JsonNode at(size_t i) const { return JsonNode(*doc_, (*v_)[i], json_index_path(path_, i)); }
  JsonObject object() const;

 private:
  const JsonDocument* doc_;
  const nlohmann::json* v_;
  std::string path_;
};

// An object whose keys the caller lists with allow(); any other key is an error.
class JsonObject {
 public:
  explicit JsonObject(JsonNode n);
  const JsonNode& node() const { return node_; }
  bool has(const std::string& key) const { return node_.value().contains(key); }
  JsonNode child(const std::string& key) const;
  std::optional<JsonNode> get(const std::string& key) const;
  JsonNode require(const std::string& key) const;
  // Fails at the first unknown key, suggesting the nearest allowed one when it is close.
  void allow(std::initializer_list<const char*> keys) const;

 private:
  JsonNode node_;
};

std::string json_quoted(const std::string& s);  // "gold" with JSON escapes

}  // namespace pdrt
