#include "renderer/scene/json_document.h"

#include "sampling/core/errors.h"
#include "sampling/core/printable.h"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>

namespace pdrt {

using json = nlohmann::json;

namespace {

// Levenshtein distance, for "did you mean" suggestions.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diag = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

// "[json.exception.parse_error.101] parse error at line 1, column 9: syntax error while
// parsing value - invalid literal; last read: 'tru}'" -> "JSON syntax error while parsing ...".
std::string short_reason(const std::string& what) {
  std::string r = what;
  if (size_t p = r.find("column "); p != std::string::npos)
    if (size_t c = r.find(": ", p); c != std::string::npos) r = r.substr(c + 2);
  const std::string prefix = "syntax error ";
  if (r.rfind(prefix, 0) == 0) r = r.substr(prefix.size());
  return "JSON syntax error " + r;
}

constexpr size_t kShownChars = 60;

// Appends a rendering of v to out, stopping once out is longer than kShownChars and eliding
// containers below `depth` levels as [...] / {...}: cost and recursion are bounded by the cap,
// not by the value.
void abbreviate(const json& v, int depth, std::string& out) {
  if (out.size() > kShownChars) return;
  if (!v.is_structured()) {
    out += v.dump();
    return;
  }
  const bool object = v.is_object();
  if (v.empty() || depth == 0) {
    out += object ? (v.empty() ? "{}" : "{...}") : (v.empty() ? "[]" : "[...]");
    return;
  }
  out += object ? '{' : '[';
  bool first = true;
  for (auto it = v.begin(); it != v.end() && out.size() <= kShownChars; ++it) {
    if (!first) out += ",";
    first = false;
    if (object) out += json(it.key()).dump() + ":";
    abbreviate(*it, depth - 1, out);
  }
  out += object ? '}' : ']';
}

}  // namespace

std::string json_quoted(const std::string& s) { return json(s).dump(); }

JsonDocument::JsonDocument(std::string name, std::string text)
    : name_(std::move(name)), text_(std::move(text)), locations_(text_) {
  if (auto deep = locations_.first_nesting_beyond(kMaxJsonDepth)) {
    // A syntax error before that point is the first problem; nlohmann's parser is iterative,
    // so parsing the (bounded-depth) prefix is safe.
    try {
      json prefix = json::parse(std::string_view(text_).substr(0, deep->begin));
    } catch (const json::parse_error& e) {
      if (e.byte && e.byte - 1 < deep->begin) fail(locations_.at_byte(e.byte - 1), short_reason(e.what()));
    } catch (const json::out_of_range&) {}
    fail(deep, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (the limit for a scene)");
  }
  try {
    root_ = json::parse(text_);
  } catch (const json::parse_error& e) {
    fail(locations_.at_byte(e.byte ? e.byte - 1 : 0), short_reason(e.what()));
  } catch (const json::out_of_range& e) {  // 406: a number beyond double range, no position given
    auto bad = locations_.first_overflowing_number();
    if (!bad) throw InputError(name_ + ": " + e.what());
    fail(bad->second, bad->first + " must be a finite number, got " + std::string(locations_.source(bad->second)));
  }
  if (auto dup = locations_.first_duplicate_key()) fail(dup->second, dup->first + " duplicate key");
}

JsonNode JsonDocument::root() const { return JsonNode(*this, root_, ""); }

std::string JsonDocument::position(const std::optional<JsonLocation>& at) const {
  return at ? name_ + ":" + std::to_string(at->line) + ":" + std::to_string(at->col) : name_;
}

void JsonDocument::fail(const std::optional<JsonLocation>& at, const std::string& message) const {
  std::string line = position(at) + ": " + message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';  // messages are one line
  throw InputError(printable(line));
}

std::string JsonNode::where() const { return printable(doc_->position(doc_->locations().value(path_)) + ": " + path_); }

void JsonNode::fail(const std::string& what) const {
  doc_->fail(doc_->locations().value(path_), (path_.empty() ? "" : path_ + " ") + what);
}

void JsonNode::fail_got(const std::string& what) const { fail(what + ", got " + shown()); }

void JsonNode::fail_key(const std::string& what) const { doc_->fail(doc_->locations().key(path_), path_ + " " + what); }

std::string JsonNode::shown() const {
  std::string s;
  if (!v_->is_structured())
    if (auto at = doc_->locations().value(path_); at && at->end > at->begin) s = doc_->locations().source(*at);
  if (s.empty()) abbreviate(*v_, 3, s);
  if (s.size() <= kShownChars) return s;
  size_t cut = kShownChars - 3;
  while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return s.substr(0, cut) + "...";
}

float JsonNode::number() const {
  if (!v_->is_number()) fail_got("must be a number");
  double d = v_->get<double>();
  if (!std::isfinite(d)) fail_got("must be a finite number");
  if (std::abs(d) > FLT_MAX) fail_got("is too large for a float");
  return float(d);
}

float JsonNode::positive() const {
  float x = number();
  if (!(x > 0)) fail_got("must be > 0");
  return x;
}

float JsonNode::non_negative() const {
  float x = number();
  if (x < 0) fail_got("must be >= 0");
  return x;
}

float JsonNode::in_unit_interval() const {
  float x = number();
  if (x < 0 || x > 1) fail_got("must be in [0,1]");
  return x;
}

long long JsonNode::integer(long long lo, long long hi) const {
  if (!v_->is_number_integer()) fail_got("must be an integer");
  if (v_->is_number_unsigned() && v_->get<uint64_t>() > uint64_t(LLONG_MAX))
    fail_got("must be an integer <= " + std::to_string(hi));
  long long x = v_->get<long long>();
  if (x < lo) fail_got("must be an integer >= " + std::to_string(lo));
  if (x > hi) fail_got("must be an integer <= " + std::to_string(hi));
  return x;
}

int JsonNode::int_at_least(int lo) const { return int(integer(lo, INT_MAX)); }

uint64_t JsonNode::integer_in(IntRange range) const {
  if (!v_->is_number_integer()) fail_got("must be an integer in " + range.str());
  if (!v_->is_number_unsigned() || !range.contains(v_->get<uint64_t>()))
    fail_got("must be an integer in " + range.str());
  return v_->get<uint64_t>();
}

bool JsonNode::boolean() const {
  if (!v_->is_boolean()) fail_got("must be true or false");
  return v_->get<bool>();
}

std::string JsonNode::string() const {
  if (!v_->is_string()) fail_got("must be a string");
  return v_->get<std::string>();
}

std::string JsonNode::choice(std::initializer_list<const char*> options) const {
  std::string s = string(), list;
  for (const char* o : options) {
    if (s == o) return s;
    list += (list.empty() ? "" : ", ") + std::string(o);
  }
  fail_got("must be one of " + list);
}

Vec3 JsonNode::vec3() const {
  if (!v_->is_array() || v_->size() != 3) fail_got("must be an array of 3 numbers");
  return {at(0).number(), at(1).number(), at(2).number()};
}

Vec3 JsonNode::nonzero_vec3() const {
  Vec3 v = vec3();
  if (is_black(v)) fail_got("must be non-zero");
  return v;
}

Vec3 JsonNode::color() const {
  Vec3 c = vec3();
  if (std::min({c.x, c.y, c.z}) < 0 || max_component(c) > 1) fail_got("must have components in [0,1]");
  return c;
}

Vec3 JsonNode::radiance() const {
  Vec3 c = vec3();
  if (std::min({c.x, c.y, c.z}) < 0) fail_got("must have components >= 0");
  return c;
}

size_t JsonNode::array_size(size_t min_size) const {
  if (!v_->is_array()) fail_got("must be an array");
  if (v_->size() < min_size) fail_got("must have at least " + std::to_string(min_size) + " elements");
  return v_->size();
}

JsonObject JsonNode::object() const { return JsonObject(*this); }

JsonObject::JsonObject(JsonNode n) : node_(std::move(n)) {
  if (!node_.value().is_object())
    node_.fail_got(node_.path().empty() ? "the scene must be a JSON object" : "must be an object");
}

JsonNode JsonObject::child(const std::string& key) const {
  return JsonNode(node_.document(), node_.value().at(key), json_key_path(node_.path(), key));
}

std::optional<JsonNode> JsonObject::get(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return child(key);
}

JsonNode JsonObject::require(const std::string& key) const {
  if (!has(key)) node_.fail("missing required key " + json_quoted(key));
  return child(key);
}

void JsonObject::allow(std::initializer_list<const char*> keys) const {
  for (auto it = node_.value().begin(); it != node_.value().end(); ++it) {
    const std::string& k = it.key();
    std::string best, list;
    size_t best_d = SIZE_MAX;
    bool ok = false;
    for (const char* a : keys) {
      ok |= k == a;
      if (size_t d = edit_distance(k, a); d < best_d) best_d = d, best = a;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    if (ok) continue;
    bool close = best_d <= 2 && best_d < k.size();  // a typo, not a different word
    child(k).fail_key(close ? "unknown key (did you mean " + json_quoted(best) + "?)"
                            : "unknown key (expected one of: " + list + ")");
  }
}

}  // namespace pdrt
